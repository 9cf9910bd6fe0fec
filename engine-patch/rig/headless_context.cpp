#include "headless_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdio>
#include <vector>

namespace host {

struct HeadlessContext::Impl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  int debugErrors = 0;
};

namespace {

bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  const std::string all = std::string(" ") + list + " ";
  return all.find(std::string(" ") + name + " ") != std::string::npos;
}

EGLContext createCoreContext(EGLDisplay display) {
  if (!eglBindAPI(EGL_OPENGL_API)) return EGL_NO_CONTEXT;
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                               4,
                               EGL_CONTEXT_MINOR_VERSION,
                               5,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK,
                               EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                               EGL_CONTEXT_OPENGL_DEBUG,
                               EGL_TRUE,
                               EGL_NONE};
  return eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
}

void GLAPIENTRY onDebugMessage(GLenum, GLenum type, GLuint, GLenum severity, GLsizei,
                               const GLchar* message, const void* user) {
  if (type == GL_DEBUG_TYPE_ERROR || severity == GL_DEBUG_SEVERITY_HIGH) {
    auto* impl = static_cast<HeadlessContext::Impl*>(const_cast<void*>(user));
    ++impl->debugErrors;
    std::fprintf(stderr, "GL debug: %s\n", message);
  }
}

}  // namespace

std::string ContextInfo::summary() const {
  return renderer + " | " + version + " | EGL " + platform + " | GL_MAX_SAMPLES " +
         std::to_string(maxSamples);
}

HeadlessContext::HeadlessContext() : impl_(std::make_unique<Impl>()) {
  const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!hasExtension(clientExtensions, "EGL_EXT_platform_base"))
    throw ContextError("EGL lacks EGL_EXT_platform_base: cannot choose a headless platform");

  std::string tried;
  // 1. A real device (NVIDIA's driver exposes its GPUs here).
  if (hasExtension(clientExtensions, "EGL_EXT_platform_device")) {
    EGLDeviceEXT devices[8];
    EGLint count = 0;
    if (eglQueryDevicesEXT(8, devices, &count)) {
      for (EGLint i = 0; i < count && impl_->context == EGL_NO_CONTEXT; ++i) {
        const char* deviceExtensions = eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS);
        // Mesa lists its software rasteriser as a device too; the surfaceless path below covers it.
        if (hasExtension(deviceExtensions, "EGL_MESA_device_software")) continue;
        EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        EGLint major = 0, minor = 0;
        if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) continue;
        EGLContext context = createCoreContext(display);
        if (context == EGL_NO_CONTEXT) {
          eglTerminate(display);
          continue;
        }
        impl_->display = display;
        impl_->context = context;
        info_.platform = "device";
      }
    }
    tried += "device";
  }
  // 2. Mesa's surfaceless platform (llvmpipe on machines without a GPU).
  if (impl_->context == EGL_NO_CONTEXT &&
      hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay display =
        eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (display != EGL_NO_DISPLAY && eglInitialize(display, &major, &minor)) {
      EGLContext context = createCoreContext(display);
      if (context != EGL_NO_CONTEXT) {
        impl_->display = display;
        impl_->context = context;
        info_.platform = "surfaceless";
      } else {
        eglTerminate(display);
      }
    }
    tried += tried.empty() ? "surfaceless" : ", surfaceless";
  }
  if (impl_->context == EGL_NO_CONTEXT)
    throw ContextError("no EGL platform gave an OpenGL 4.5 core context (tried: " +
                       (tried.empty() ? std::string("none available") : tried) + ")");
  if (!eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, impl_->context))
    throw ContextError("eglMakeCurrent without a surface failed (needs EGL_KHR_surfaceless_context)");

  info_.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  info_.version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  glGetIntegerv(GL_MAX_SAMPLES, &info_.maxSamples);
  info_.stencilExport = epoxy_has_gl_extension("GL_ARB_shader_stencil_export");
  if (epoxy_gl_version() < 45)
    throw ContextError("context is OpenGL " + info_.version + ", retroaa needs 4.5 core");
  if (epoxy_has_gl_extension("GL_KHR_debug")) {
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, impl_.get());
  }
}

HeadlessContext::~HeadlessContext() {
  eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(impl_->display, impl_->context);
  eglTerminate(impl_->display);
}

int HeadlessContext::debugErrorCount() const { return impl_->debugErrors; }

}  // namespace host
