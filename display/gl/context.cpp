#include "display/gl/context.h"

#include "config/error.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <vector>

namespace cavewall::display::gl {

namespace {

const char* severityName(GLenum severity) {
    switch (severity) {
        case GL_DEBUG_SEVERITY_HIGH: return "high";
        case GL_DEBUG_SEVERITY_MEDIUM: return "medium";
        case GL_DEBUG_SEVERITY_LOW: return "low";
        default: return "note";
    }
}

void GLAPIENTRY printDebugMessage(GLenum, GLenum type, GLuint id, GLenum severity, GLsizei, const GLchar* message,
                                  const void*) {
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    std::cerr << "cavewall: GL " << severityName(severity) << (type == GL_DEBUG_TYPE_ERROR ? " error" : "") << " ("
              << id << "): " << message << "\n";
}

std::string glString(GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return s ? s : "?";
}

thread_local Context* tCurrent = nullptr;                // Context::current()
thread_local std::vector<CurrentContextScope*> tScopes;  // this thread's open scopes, innermost last

}  // namespace

Context::~Context() {
    if (tCurrent == this) tCurrent = nullptr;
    for (CurrentContextScope* scope : tScopes)
        if (scope->_saved == this) scope->_saved = nullptr;
}

CurrentContextScope::CurrentContextScope() : _saved(Context::current()) { tScopes.push_back(this); }

CurrentContextScope::~CurrentContextScope() {
    tScopes.erase(std::find(tScopes.begin(), tScopes.end(), this));
    if (_saved && Context::current() != _saved) _saved->makeCurrent();
}

void Context::makeCurrent() {
    makeCurrentOnThread();
    tCurrent = this;
}

Context* Context::current() { return tCurrent; }

void Context::becameCurrent() { tCurrent = this; }

bool ContextOptions::defaultDebug() {
#ifndef NDEBUG
    return true;
#else
    const char* env = std::getenv("CAVEWALL_GL_DEBUG");
    return env && std::string(env) == "1";
#endif
}

void Context::present(int window, const PresentImage&, scenes::Image*) {
    throw Error("cannot show an image in window " + std::to_string(window) + ": the " + _info.provider +
                " context has no windows");
}

void initialiseCurrentContext(ContextInfo& info, const ContextOptions& options) {
    info.renderer = glString(GL_RENDERER);
    info.version = glString(GL_VERSION);
    if (epoxy_gl_version() < 45)
        throw Error(info.provider + " context: expected OpenGL 4.5 core, got " + info.version + " (" + info.renderer +
                    ")");
    if (options.debug) {
        // Synchronous, so a message is printed from inside the call that caused it.
        glEnable(GL_DEBUG_OUTPUT);
        glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
        glDebugMessageCallback(printDebugMessage, nullptr);
    }
}

std::vector<WindowRequest> windowRequests(const display::Display& display) {
    std::vector<WindowRequest> out;
    for (const config::Screen& s : display.screens()) {
        WindowRequest w;
        w.title = display.config().name + ": " + s.name;
        w.size = s.resolution;
        if (s.window) {
            if (s.window->size != glm::ivec2(0)) w.size = s.window->size;
            w.position = s.window->position;
            w.monitor = s.window->monitor;
            w.fullscreen = s.window->fullscreen;
            w.borderless = s.window->borderless;
        }
        out.push_back(w);
    }
    return out;
}

std::string windowsUnavailableReason() {
#ifdef CAVEWALL_WITH_GLFW
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((x11 && *x11) || (wayland && *wayland)) return "";
    return "no window system ($DISPLAY and $WAYLAND_DISPLAY are unset)";
#else
    return "this cavewall was built without GLFW (CAVEWALL_WITH_GLFW=OFF)";
#endif
}

#ifndef CAVEWALL_WITH_GLFW
std::unique_ptr<Context> createWindowedContext(const std::vector<WindowRequest>&, bool, const ContextOptions&) {
    throw Error(
        "windowed output: this cavewall was built without GLFW (CAVEWALL_WITH_GLFW=OFF); "
        "render headless instead");
}
#endif

}  // namespace cavewall::display::gl
