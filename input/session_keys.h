#pragma once
// The keys of a windowed session that do not navigate: the help page and quitting. Pure: window
// events in, two flags out.
//   F1 or H     toggles the help page
//   Escape      with the pointer captured: nothing here (the window releases the pointer);
//               with the pointer free: quit. So the first Escape after a click frees the
//               pointer and the second one quits.
//   Ctrl+Q      quit
// PointerCapture events say whether a window holds the pointer; the window sends the Escape key
// before the release it causes (display::gl::Context::takeInputEvents).

#include "input/sample.h"

namespace cavewall::input {

class SessionKeys {
public:
    void handle(const Event& event);
    bool helpShown() const { return _help; }
    bool quitRequested() const { return _quit; }
    bool pointerCaptured() const { return _captured; }

private:
    bool _help = false;
    bool _quit = false;
    bool _captured = false;
    bool _control = false;
};

}  // namespace cavewall::input
