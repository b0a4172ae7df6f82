#include "display/gl/context.h"

#include "config/error.h"
#include "display/gl/gl_object.h"
#include "display/gl/overlay_pass.h"
#include "display/gl/render_targets.h"
#include "display/window_layout.h"

#include <memory>
#include <utility>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace cavewall::display::gl {

namespace {

std::string glfwFailure() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "no reason given";
}

// GLFW is process-wide: the first live context initialises it, the last one terminates it.
int gLiveGlfwContexts = 0;

class GlfwContext final : public Context {
public:
    GlfwContext(const std::vector<WindowRequest>& requests, bool stereo, const ContextOptions& options);
    ~GlfwContext() override;

    void makeCurrentOnThread() override { glfwMakeContextCurrent(_windows.front().handle); }
    int windowCount() const override { return static_cast<int>(_windows.size()); }
    glm::ivec2 windowPixels(int window) const override;
    void present(int window, const PresentImage& image, scenes::Image* capture) override;
    bool pollCloseRequested() override;
    std::vector<input::Event> takeInputEvents() override;
    void setOverlay(int window, const display::OverlayText& overlay) override;
    void setTitle(int window, const std::string& title) override;
    void requestWindowCapture(int window) override { at(window).captureRequested = true; }
    std::optional<scenes::Image> takeWindowCapture(int window) override {
        return std::exchange(at(window).capture, {});
    }

private:
    static GlfwContext& of(GLFWwindow* w) { return *static_cast<GlfwContext*>(glfwGetWindowUserPointer(w)); }
    static void onKey(GLFWwindow* w, int key, int scancode, int action, int mods);
    static void onButton(GLFWwindow* w, int button, int action, int mods);
    static void onCursor(GLFWwindow* w, double x, double y);
    static void onScroll(GLFWwindow* w, double dx, double dy);
    void push(input::EventType type, int code, glm::dvec2 value = glm::dvec2(0.0)) {
        _events.push_back({type, 0.0, code, value});
    }

    struct Window {
        GLFWwindow* handle = nullptr;
        GlObject readFramebuffer;                  // belongs to this window's context (framebuffers are not shared)
        std::unique_ptr<OverlayPass> overlayPass;  // this window's context too; made when first needed
        display::OverlayText overlay;
        std::vector<display::OverlayVertex> overlayVertices;
        int overlayWidth = -1;  // the window width overlayVertices were laid out for
        std::string title;
        bool captureRequested = false;
        std::optional<scenes::Image> capture;
    };
    Window& at(int window);
    void drawOverlay(Window& w, glm::ivec2 windowSize);
    void open(const WindowRequest& request, const display::WindowPlacement& place, GLFWmonitor* fullscreen, bool stereo,
              const ContextOptions& options);
    void blit(Window& w, unsigned texture, glm::ivec2 size, bool fill, GLenum drawBuffer, glm::ivec2 windowSize);

    std::vector<Window> _windows;
    std::vector<input::Event> _events;
    GLFWwindow* _captured = nullptr;  // the window holding the pointer, if any
    glm::dvec2 _lastCursor{0.0};
};

GlfwContext::GlfwContext(const std::vector<WindowRequest>& requests, bool stereo, const ContextOptions& options) {
    if (requests.empty()) throw Error("windowed output: expected at least one window, got none");
    if (gLiveGlfwContexts == 0 && !glfwInit())
        throw Error("windowed output: cannot start GLFW (" + glfwFailure() + ")");
    ++gLiveGlfwContexts;
    _info.provider = "GLFW";
    try {
        // The monitors' work areas (GLFW's order), and each window's place on them.
        int count = 0;
        GLFWmonitor** monitors = glfwGetMonitors(&count);
        std::vector<display::MonitorArea> areas;
        for (int m = 0; m < count; ++m) {
            display::MonitorArea a;
            glfwGetMonitorWorkarea(monitors[m], &a.position.x, &a.position.y, &a.size.x, &a.size.y);
            if (a.size.x <= 0 || a.size.y <= 0) {  // no work area reported: the whole mode
                const GLFWvidmode* mode = glfwGetVideoMode(monitors[m]);
                glfwGetMonitorPos(monitors[m], &a.position.x, &a.position.y);
                a.size = mode ? glm::ivec2(mode->width, mode->height) : glm::ivec2(1920, 1080);
            }
            areas.push_back(a);
        }
        if (areas.empty()) areas.push_back({{0, 0}, {1920, 1080}});  // no monitor reported
        std::vector<display::WindowWish> wishes;
        for (const WindowRequest& r : requests)
            wishes.push_back({r.title, r.size, r.position, r.monitor, r.fullscreen, r.borderless});
        const std::vector<display::WindowPlacement> places = display::layoutWindows(wishes, areas);
        for (std::size_t i = 0; i < requests.size(); ++i)
            open(requests[i], places[i],
                 requests[i].fullscreen && requests[i].monitor < count ? monitors[requests[i].monitor] : nullptr,
                 stereo, options);
        makeCurrent();
        initialiseCurrentContext(_info, options);
        GLboolean hasStereo = GL_FALSE;
        glGetBooleanv(GL_STEREO, &hasStereo);
        _info.stereoWindows = hasStereo == GL_TRUE;
    } catch (...) {
        for (Window& w : _windows) glfwDestroyWindow(w.handle);
        if (--gLiveGlfwContexts == 0) glfwTerminate();
        throw;
    }
}

GlfwContext::~GlfwContext() {
    for (Window& w : _windows) {
        glfwMakeContextCurrent(w.handle);
        w.readFramebuffer.reset();
        w.overlayPass.reset();
        glfwMakeContextCurrent(nullptr);
        glfwDestroyWindow(w.handle);
    }
    if (--gLiveGlfwContexts == 0) glfwTerminate();
}

void GlfwContext::open(const WindowRequest& r, const display::WindowPlacement& place, GLFWmonitor* monitor, bool stereo,
                       const ContextOptions& options) {
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_STEREO, stereo ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_DECORATED, r.borderless ? GLFW_FALSE : GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);  // shown once placed, so it never appears elsewhere first
    const glm::ivec2 size = monitor ? r.size : place.size;
    GLFWwindow* share = _windows.empty() ? nullptr : _windows.front().handle;
    GLFWwindow* handle = glfwCreateWindow(size.x, size.y, r.title.c_str(), monitor, share);
    if (!handle)
        throw Error("window '" + r.title + "': cannot open a " + std::to_string(size.x) + " x " +
                    std::to_string(size.y) + (stereo ? " quad-buffer stereo" : "") + " window with OpenGL 4.5 core (" +
                    glfwFailure() + ")");
    if (!monitor) glfwSetWindowPos(handle, place.position.x, place.position.y);
    glfwShowWindow(handle);
    glfwMakeContextCurrent(handle);
    glfwSwapInterval(0);  // several windows swap in turn; waiting for vsync on each would stack up
    glfwSetWindowUserPointer(handle, this);
    glfwSetKeyCallback(handle, onKey);
    glfwSetMouseButtonCallback(handle, onButton);
    glfwSetCursorPosCallback(handle, onCursor);
    glfwSetScrollCallback(handle, onScroll);
    _windows.push_back({});
    _windows.back().handle = handle;
    _windows.back().title = r.title;
}

GlfwContext::Window& GlfwContext::at(int window) {
    if (window < 0 || window >= windowCount())
        throw Error("window: expected a window index in [0, " + std::to_string(windowCount() - 1) + "], got " +
                    std::to_string(window));
    return _windows[window];
}

glm::ivec2 GlfwContext::windowPixels(int window) const {
    if (window < 0 || window >= windowCount()) return {0, 0};
    glm::ivec2 size{0, 0};
    glfwGetFramebufferSize(_windows[window].handle, &size.x, &size.y);
    return size;
}

void GlfwContext::setOverlay(int window, const display::OverlayText& overlay) {
    Window& w = at(window);
    if (overlay == w.overlay) return;
    w.overlay = overlay;
    w.overlayWidth = -1;  // laid out again at the next present, for the window's width
}

void GlfwContext::setTitle(int window, const std::string& title) {
    Window& w = at(window);
    if (title == w.title) return;
    w.title = title;
    glfwSetWindowTitle(w.handle, title.c_str());
}

// In the window's context, over its back buffer (both of a stereo window's).
void GlfwContext::drawOverlay(Window& w, glm::ivec2 windowSize) {
    if (w.overlayWidth != windowSize.x) {  // a narrow window gets smaller text (display::fitOverlay)
        w.overlayVertices = display::layoutOverlay(display::fitOverlay(w.overlay, static_cast<float>(windowSize.x)));
        w.overlayWidth = windowSize.x;
    }
    if (w.overlayVertices.empty()) return;
    if (!w.overlayPass) w.overlayPass = std::make_unique<OverlayPass>();
    glDrawBuffer(GL_BACK);
    w.overlayPass->draw(w.overlayVertices, windowSize);
}

void GlfwContext::blit(Window& w, unsigned texture, glm::ivec2 size, bool fill, GLenum drawBuffer,
                       glm::ivec2 windowSize) {
    glNamedFramebufferTexture(w.readFramebuffer.id(), GL_COLOR_ATTACHMENT0, texture, 0);
    glNamedFramebufferReadBuffer(w.readFramebuffer.id(), GL_COLOR_ATTACHMENT0);
    // Bind-to-edit for the window's framebuffer: Mesa 22 mishandles the DSA calls on framebuffer 0.
    glBindFramebuffer(GL_READ_FRAMEBUFFER, w.readFramebuffer.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glDrawBuffer(drawBuffer);
    // The image whole and undistorted in a window of another shape: black bars beside it; or,
    // when its screen took the window's shape, over the whole window.
    const glm::ivec4 to = fill ? glm::ivec4(0, 0, windowSize.x, windowSize.y) : fitImage(size, windowSize);
    if (to != glm::ivec4(0, 0, windowSize.x, windowSize.y)) {
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    const GLenum filter = glm::ivec2(to.z - to.x, to.w - to.y) == size ? GL_NEAREST : GL_LINEAR;
    glBlitFramebuffer(0, 0, size.x, size.y, to.x, to.y, to.z, to.w, GL_COLOR_BUFFER_BIT, filter);
}

void GlfwContext::present(int window, const PresentImage& image, scenes::Image* capture) {
    Window& w = at(window);
    glFinish();  // the rendering context's writes must be complete before another context reads them
    glfwMakeContextCurrent(w.handle);
    if (!w.readFramebuffer) w.readFramebuffer = createFramebuffer();
    glm::ivec2 windowSize{0, 0};
    glfwGetFramebufferSize(w.handle, &windowSize.x, &windowSize.y);
    // The images hold sRGB-encoded bytes and the window shows bytes as sRGB: copy them unchanged.
    glDisable(GL_FRAMEBUFFER_SRGB);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const bool stereo = _info.stereoWindows;
    blit(w, image.left, image.size, image.fill, stereo ? GL_BACK_LEFT : GL_BACK, windowSize);
    if (stereo && image.right) blit(w, image.right, image.size, image.fill, GL_BACK_RIGHT, windowSize);
    drawOverlay(w, windowSize);
    const GLenum shown = stereo ? GL_BACK_LEFT : GL_BACK;
    if (capture) *capture = readFramebuffer(0, shown, windowSize, "window " + std::to_string(window));
    if (std::exchange(w.captureRequested, false))
        w.capture = readFramebuffer(0, shown, windowSize, "window " + std::to_string(window));
    glfwSwapBuffers(w.handle);
    makeCurrent();
}

bool GlfwContext::pollCloseRequested() {
    glfwPollEvents();
    for (const Window& w : _windows)
        if (glfwWindowShouldClose(w.handle)) return true;
    return false;
}

void GlfwContext::onKey(GLFWwindow* w, int key, int, int action, int) {
    if (action == GLFW_REPEAT) return;
    GlfwContext& c = of(w);
    int code = -1;
    if ((key >= GLFW_KEY_A && key <= GLFW_KEY_Z) || (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) || key == GLFW_KEY_SPACE)
        code = key;  // GLFW's printable key codes are their upper-case ASCII codes
    else if (key == GLFW_KEY_LEFT_SHIFT || key == GLFW_KEY_RIGHT_SHIFT)
        code = input::kKeyShift;
    else if (key == GLFW_KEY_ESCAPE)
        code = input::kKeyEscape;
    else if (key == GLFW_KEY_LEFT_CONTROL || key == GLFW_KEY_RIGHT_CONTROL)
        code = input::kKeyControl;
    else if (key == GLFW_KEY_F1)
        code = input::kKeyF1;
    if (code < 0) return;
    c.push(action == GLFW_PRESS ? input::EventType::KeyDown : input::EventType::KeyUp, code);
    if (code == input::kKeyEscape && action == GLFW_PRESS && c._captured) {  // after the key: see context.h
        glfwSetInputMode(c._captured, GLFW_CURSOR, GLFW_CURSOR_NORMAL);
        c._captured = nullptr;
        c.push(input::EventType::PointerCapture, 0);
    }
}

void GlfwContext::onButton(GLFWwindow* w, int button, int action, int) {
    if (button != GLFW_MOUSE_BUTTON_LEFT && button != GLFW_MOUSE_BUTTON_RIGHT) return;
    GlfwContext& c = of(w);
    if (!c._captured && button == GLFW_MOUSE_BUTTON_LEFT && action == GLFW_PRESS) {
        c._captured = w;  // the first click only captures the pointer
        glfwSetInputMode(w, GLFW_CURSOR, GLFW_CURSOR_DISABLED);
        glfwGetCursorPos(w, &c._lastCursor.x, &c._lastCursor.y);
        c.push(input::EventType::PointerCapture, 1);
        return;
    }
    c.push(action == GLFW_PRESS ? input::EventType::ButtonDown : input::EventType::ButtonUp,
           button == GLFW_MOUSE_BUTTON_LEFT ? 0 : 1);
}

void GlfwContext::onCursor(GLFWwindow* w, double x, double y) {
    GlfwContext& c = of(w);
    if (c._captured != w) return;
    const glm::dvec2 p(x, y), d = p - c._lastCursor;
    c._lastCursor = p;
    if (d != glm::dvec2(0.0)) c.push(input::EventType::MouseMove, 0, d);
}

void GlfwContext::onScroll(GLFWwindow* w, double, double dy) { of(w).push(input::EventType::Scroll, 0, {0.0, dy}); }

std::vector<input::Event> GlfwContext::takeInputEvents() {
    glfwPollEvents();
    return std::exchange(_events, {});
}

}  // namespace

std::unique_ptr<Context> createWindowedContext(const std::vector<WindowRequest>& windows, bool stereo,
                                               const ContextOptions& options) {
    return std::make_unique<GlfwContext>(windows, stereo, options);
}

}  // namespace cavewall::display::gl
