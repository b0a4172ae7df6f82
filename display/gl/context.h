#pragma once
// OpenGL 4.5 core contexts behind one small interface, so the renderer never knows where it
// runs. Two providers:
//  - headless (EGL, no surface): the renderer draws into framebuffer objects only. Display
//    choice: EGL_PLATFORM_SURFACELESS_MESA, else the first EGL device
//    (EGL_PLATFORM_DEVICE_EXT), else eglGetDisplay(EGL_DEFAULT_DISPLAY).
//  - windowed (GLFW, optional at build time with CAVEWALL_WITH_GLFW): one window per screen;
//    window 0's context is the rendering context and the others share its objects, so the
//    offscreen images the renderer made can be shown in every window.
// GL entry points come from libepoxy. A context is made current on the calling thread when it
// is created. Debug contexts (ContextOptions::debug, the default in debug builds) install a
// KHR_debug callback that prints driver messages on stderr.

#include "display/display.h"
#include "display/overlay_text.h"
#include "input/sample.h"
#include "scenes/scene.h"

#include <glm/glm.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace cavewall::display::gl {

// Which EGL platform a headless context uses; Auto tries them in the order above.
enum class HeadlessPlatform { Auto, Surfaceless, Device, Default };

struct ContextOptions {
    HeadlessPlatform headless = HeadlessPlatform::Auto;  // headless contexts only
    // A debug context with the KHR_debug callback: on in debug builds, and wherever the
    // environment has CAVEWALL_GL_DEBUG=1.
    bool debug = defaultDebug();

    static bool defaultDebug();
};

struct ContextInfo {
    std::string provider;        // "EGL surfaceless", "EGL device", "EGL default", "GLFW"
    std::string renderer;        // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string version;         // GL_VERSION
    bool stereoWindows = false;  // windows have GL_BACK_LEFT and GL_BACK_RIGHT (quad-buffer)
};

// What the renderer produced for one screen, to be shown in a window: colour textures (in the
// rendering context's share group) of `size` pixels. `right` is the quad-buffer right eye.
struct PresentImage {
    unsigned left = 0;   // GL texture name
    unsigned right = 0;  // GL texture name or 0
    glm::ivec2 size{0, 0};
    bool fill = false;  // stretched over the whole window (its screen took the window's shape),
                        // else whole and undistorted between black bars
};

class Context {
public:
    virtual ~Context();  // no longer current() on the thread that destroys it
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    const ContextInfo& info() const { return _info; }
    // Makes the rendering context current on this thread.
    void makeCurrent();
    // The context made current on the calling thread last (by makeCurrent or by its creation);
    // null when there was none, or it has been destroyed since.
    static Context* current();

    // Windows, in the order they were requested (none for headless contexts).
    virtual int windowCount() const { return 0; }
    // Window `window`'s drawable size in pixels now; {0, 0} when minimised or headless.
    virtual glm::ivec2 windowPixels(int /*window*/) const { return {0, 0}; }
    // Shows `image` in window `window`, scaled to the window, and swaps its buffers. When
    // `capture` is given it receives what the window's back buffer held just before the swap
    // (8-bit RGBA, rows top to bottom, the window's size). Leaves the rendering context current.
    virtual void present(int window, const PresentImage& image, scenes::Image* capture = nullptr);
    // Processes window events; true once the user asked to close any window.
    virtual bool pollCloseRequested() { return false; }
    // Text drawn over window `window` at every present from now on (display/overlay_text.h;
    // no lines: none). Only the window shows it: images the renderer reads back never hold it.
    virtual void setOverlay(int /*window*/, const display::OverlayText& /*overlay*/) {}
    // Sets window `window`'s title (nothing is sent when it is unchanged).
    virtual void setTitle(int /*window*/, const std::string& /*title*/) {}
    // Asks for what window `window` shows (the image and its overlay) at its next present;
    // takeWindowCapture then gives it once (8-bit RGBA, rows top to bottom, the window's
    // size), and nullopt before that or without windows.
    virtual void requestWindowCapture(int /*window*/) {}
    virtual std::optional<scenes::Image> takeWindowCapture(int /*window*/) { return std::nullopt; }
    // Keyboard and mouse events of the windows since the last call, for the desktop fallback
    // (input/desktop_navigator.h, input/session_keys.h): keys (printable keys as upper-case
    // ASCII, Shift, Control, Escape, F1), mouse buttons 0 (left) and 1 (right), wheel steps, and
    // pointer motion in pixels while the pointer is captured. A left click in a window
    // captures the pointer: that click gives PointerCapture 1 instead of a ButtonDown (its
    // ButtonUp follows). Escape releases it: KeyDown Escape, then PointerCapture 0. Event
    // times are 0: the caller stamps them with its own clock. Headless contexts have none.
    virtual std::vector<input::Event> takeInputEvents() { return {}; }

protected:
    Context() = default;
    // Providers: make the rendering context current, and say when creation made it current.
    virtual void makeCurrentOnThread() = 0;
    void becameCurrent();
    ContextInfo _info;
};

// Code that makes a context of its own current (the baker, without its caller's context) leaves
// the calling thread's as it found it: the context current() when the scope starts is made
// current again when it ends. Nothing is done when none was current, or when that context was
// destroyed in the meantime (on this thread, as contexts are). Scopes nest on one thread.
class CurrentContextScope {
public:
    CurrentContextScope();
    ~CurrentContextScope();
    CurrentContextScope(const CurrentContextScope&) = delete;
    CurrentContextScope& operator=(const CurrentContextScope&) = delete;

private:
    friend class Context;
    Context* _saved;
};

// A headless context. Throws cavewall::Error when no EGL display offers GL 4.5 core, saying
// which displays were tried.
std::unique_ptr<Context> createHeadlessContext(const ContextOptions& options = {});

struct WindowRequest {
    std::string title;
    glm::ivec2 size{0, 0};               // pixels, as wished (tiled windows may get less)
    std::optional<glm::ivec2> position;  // content's top-left relative to the monitor; none: tiled
    int monitor = 0;                     // monitor index, windowed or fullscreen
    bool fullscreen = false;
    bool borderless = false;  // undecorated
};

// One window per screen of `display`: the screen's window output when it has one, else a
// window of the screen's resolution, tiled. Windows without a position are tiled over their
// monitor's work area without overlap, scaled down to fit when needed
// (display/window_layout.h); images keep the screens' resolution.
std::vector<WindowRequest> windowRequests(const display::Display& display);

// A windowed context with `windows` (at least one); `stereo` asks for quad-buffer windows.
// Throws Error when GLFW cannot open them, or when the build has no GLFW.
std::unique_ptr<Context> createWindowedContext(const std::vector<WindowRequest>& windows, bool stereo,
                                               const ContextOptions& options = {});

// Why windows cannot be opened here, or "" when they can: this build has no GLFW, or no window
// system is reachable ($DISPLAY and $WAYLAND_DISPLAY are unset).
std::string windowsUnavailableReason();
inline bool windowSystemAvailable() { return windowsUnavailableReason().empty(); }

// Fills renderer and version from the current context and, for debug contexts, installs the
// KHR_debug callback. For providers.
void initialiseCurrentContext(ContextInfo& info, const ContextOptions& options);

}  // namespace cavewall::display::gl
