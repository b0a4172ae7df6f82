#include "display/gl/context.h"

#include "config/error.h"

#include <epoxy/egl.h>

#include <sstream>

namespace cavewall::display::gl {

namespace {

class EglContext final : public Context {
public:
    EglContext(EGLDisplay display, EGLContext context, std::string provider, const ContextOptions& options)
        : _display(display), _context(context) {
        _info.provider = std::move(provider);
        becameCurrent();  // createCoreContext made it current
        try {
            initialiseCurrentContext(_info, options);
        } catch (...) {
            release();
            throw;
        }
    }
    // The EGL display stays initialised: displays are process-wide and may serve other contexts.
    ~EglContext() override { release(); }
    void makeCurrentOnThread() override { eglMakeCurrent(_display, EGL_NO_SURFACE, EGL_NO_SURFACE, _context); }

private:
    void release() {
        if (eglGetCurrentContext() == _context)
            eglMakeCurrent(_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(_display, _context);
    }

    EGLDisplay _display;
    EGLContext _context;
};

struct Candidate {
    std::string name;
    EGLDisplay display = EGL_NO_DISPLAY;
};

std::string hex(EGLint code) {
    std::ostringstream s;
    s << "0x" << std::hex << code;
    return s.str();
}

// In order of preference: no window system at all, then a GPU device, then whatever EGL picks.
std::vector<Candidate> candidateDisplays(HeadlessPlatform wanted) {
    const bool any = wanted == HeadlessPlatform::Auto;
    std::vector<Candidate> out;
    if (any || wanted == HeadlessPlatform::Surfaceless) {
        if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless"))
            out.push_back({"EGL surfaceless",
                           eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr)});
        else
            out.push_back({"EGL surfaceless", EGL_NO_DISPLAY});
    }
    if (any || wanted == HeadlessPlatform::Device) {
        EGLDeviceEXT device = nullptr;
        EGLint count = 0;
        const bool ok = epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_enumeration") &&
                        epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_device") &&
                        eglQueryDevicesEXT(1, &device, &count) && count > 0;
        out.push_back(
            {"EGL device", ok ? eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr) : EGL_NO_DISPLAY});
    }
    if (any || wanted == HeadlessPlatform::Default) out.push_back({"EGL default", eglGetDisplay(EGL_DEFAULT_DISPLAY)});
    return out;
}

EGLContext fail(std::string& why, std::string text) {
    why = std::move(text);
    return EGL_NO_CONTEXT;
}

// A GL 4.5 core context on `display`, current and surfaceless; EGL_NO_CONTEXT with `why` set
// when the display cannot give one.
EGLContext createCoreContext(EGLDisplay display, bool debug, std::string& why) {
    EGLint major = 0, minor = 0;
    if (display == EGL_NO_DISPLAY) return fail(why, "not offered by this EGL (extension or device missing)");
    if (!eglInitialize(display, &major, &minor)) return fail(why, "eglInitialize failed, error " + hex(eglGetError()));
    if (!eglBindAPI(EGL_OPENGL_API)) return fail(why, "no desktop OpenGL API");
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!epoxy_has_egl_extension(display, "EGL_KHR_no_config_context")) {
        const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLint count = 0;
        if (!eglChooseConfig(display, wanted, &config, 1, &count) || count < 1)
            return fail(why, "no OpenGL-renderable config");
    }
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 4,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_CONTEXT_OPENGL_DEBUG,
                                 debug ? EGL_TRUE : EGL_FALSE,
                                 EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, attributes);
    if (context == EGL_NO_CONTEXT) return fail(why, "no OpenGL 4.5 core context, error " + hex(eglGetError()));
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        const EGLint error = eglGetError();
        eglDestroyContext(display, context);
        return fail(why, "cannot make a context current without a surface, error " + hex(error));
    }
    return context;
}

}  // namespace

std::unique_ptr<Context> createHeadlessContext(const ContextOptions& options) {
    std::string tried;
    for (const Candidate& c : candidateDisplays(options.headless)) {
        std::string why;
        if (EGLContext context = createCoreContext(c.display, options.debug, why); context != EGL_NO_CONTEXT)
            return std::make_unique<EglContext>(c.display, context, c.name, options);
        tried += (tried.empty() ? "" : "; ") + c.name + ": " + why;
    }
    throw Error("headless OpenGL: expected an EGL display with an OpenGL 4.5 core context, got none (" + tried + ")");
}

}  // namespace cavewall::display::gl
