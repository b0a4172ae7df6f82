// The keyboard as a wand for a tracked CAVE (input/keyboard_wand.h).
#include "input/keyboard_wand.h"
#include "input/navigator.h"

#include <gtest/gtest.h>

namespace cavewall::input {
namespace {

Event key(int code, bool down = true) { return {down ? EventType::KeyDown : EventType::KeyUp, 0.0, code, {}}; }

TEST(KeyboardWand, WasdPushTheJoystickWhileHeld) {
    KeyboardWand keys;
    WandState tracked;
    tracked.joystick = {0.25, -0.5};
    tracked.buttons = 1;
    EXPECT_EQ(keys.apply(tracked), tracked) << "no key held: the tracked wand as it is";
    keys.handle(key('W'));
    keys.handle(key('D'));
    const WandState pushed = keys.apply(tracked);
    EXPECT_EQ(pushed.joystick, glm::dvec2(1.0, 1.0));
    EXPECT_EQ(pushed.buttons, 1u) << "buttons stay the tracked wand's";
    keys.handle(key('S'));  // W and S cancel
    EXPECT_EQ(keys.apply(tracked).joystick, glm::dvec2(1.0, 0.0));
    keys.handle(key('W', false));
    keys.handle(key('S', false));
    keys.handle(key('D', false));
    EXPECT_EQ(keys.apply(tracked), tracked);
}

TEST(KeyboardWand, DigitsPickTheModeAndControlLetterKeysAreIgnored) {
    KeyboardWand keys;
    const std::optional<Event> walk = keys.handle(key('2'));
    ASSERT_TRUE(walk);
    EXPECT_EQ(walk->type, EventType::SelectMode);
    EXPECT_EQ(walk->code, static_cast<int>(NavMode::Walk));
    EXPECT_FALSE(keys.handle(key('5')));
    keys.handle(key(kKeyControl));
    keys.handle(key('W'));  // Ctrl+W: not a movement
    EXPECT_EQ(keys.apply({}).joystick, glm::dvec2(0.0));
}

}  // namespace
}  // namespace cavewall::input
