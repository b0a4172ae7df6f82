// The session's own keys (input/session_keys.h): the help page and quitting.
#include "input/session_keys.h"

#include <gtest/gtest.h>

namespace cavewall::input {
namespace {

void key(SessionKeys& keys, int code, bool down = true) {
    keys.handle({down ? EventType::KeyDown : EventType::KeyUp, 0.0, code, {}});
}

void capture(SessionKeys& keys, bool captured) { keys.handle({EventType::PointerCapture, 0.0, captured ? 1 : 0, {}}); }

TEST(SessionKeys, F1AndHToggleTheHelp) {
    SessionKeys keys;
    EXPECT_FALSE(keys.helpShown());
    key(keys, kKeyF1);
    EXPECT_TRUE(keys.helpShown());
    key(keys, kKeyF1, false);  // releasing changes nothing
    EXPECT_TRUE(keys.helpShown());
    key(keys, 'H');
    EXPECT_FALSE(keys.helpShown());
    EXPECT_FALSE(keys.quitRequested());
}

TEST(SessionKeys, EscapeFreesTheCapturedPointerFirstAndQuitsSecond) {
    SessionKeys keys;
    capture(keys, true);  // a click captured the pointer
    key(keys, kKeyEscape);
    EXPECT_FALSE(keys.quitRequested());  // the window frees the pointer: Escape, then the release
    capture(keys, false);
    key(keys, kKeyEscape);
    EXPECT_TRUE(keys.quitRequested());
}

TEST(SessionKeys, EscapeWithAFreePointerQuitsAtOnce) {
    SessionKeys keys;
    key(keys, kKeyEscape);
    EXPECT_TRUE(keys.quitRequested());
}

TEST(SessionKeys, ControlQQuitsAndQAloneDoesNot) {
    SessionKeys keys;
    key(keys, 'Q');
    EXPECT_FALSE(keys.quitRequested());  // Q flies down
    key(keys, kKeyControl);
    key(keys, 'H');  // Ctrl+H is not the help key
    EXPECT_FALSE(keys.helpShown());
    key(keys, 'Q');
    EXPECT_TRUE(keys.quitRequested());
}

TEST(SessionKeys, ReleasingControlEndsTheChord) {
    SessionKeys keys;
    key(keys, kKeyControl);
    key(keys, kKeyControl, false);
    key(keys, 'Q');
    EXPECT_FALSE(keys.quitRequested());
}

}  // namespace
}  // namespace cavewall::input
