#include "input/session_keys.h"

namespace cavewall::input {

void SessionKeys::handle(const Event& e) {
    if (e.type == EventType::PointerCapture) _captured = e.code != 0;
    if (e.type == EventType::KeyUp && e.code == kKeyControl) _control = false;
    if (e.type != EventType::KeyDown) return;
    if (e.code == kKeyControl) _control = true;
    if (e.code == kKeyF1 || (e.code == 'H' && !_control)) _help = !_help;
    if ((e.code == kKeyEscape && !_captured) || (e.code == 'Q' && _control)) _quit = true;
}

}  // namespace cavewall::input
