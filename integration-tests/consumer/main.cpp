// A tiny engine of our own that uses retroaa the way a third party does: through the installed
// package, pkg-config or add_subdirectory. One headless frame: an EGL surfaceless context, a
// three-attachment G-buffer, the plugin created on it, resolve, shade, post; no GL error allowed.
#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <retroaa/plugin.h>

#include <cstdio>
#include <cstring>

namespace {

int fail(const char* what) {
  std::fprintf(stderr, "consumer: %s\n", what);
  return 1;
}

bool makeContext() {
  EGLDisplay display = EGL_NO_DISPLAY;
  if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless"))
    display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr) || !eglBindAPI(EGL_OPENGL_API))
    return false;
  const EGLint attributes[] = {
      EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  const EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  return context != EGL_NO_CONTEXT && eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context);
}

GLuint texture(GLenum format, int width, int height) {
  GLuint name = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &name);
  glTextureStorage2D(name, 1, format, width, height);
  return name;
}

GLuint framebuffer(GLuint color, GLuint depthStencil = 0) {
  GLuint name = 0;
  glCreateFramebuffers(1, &name);
  glNamedFramebufferTexture(name, GL_COLOR_ATTACHMENT0, color, 0);
  if (depthStencil) glNamedFramebufferTexture(name, GL_DEPTH_STENCIL_ATTACHMENT, depthStencil, 0);
  return name;
}

}  // namespace

int main() {
  if (std::strcmp(retroaa::version(), RETROAA_VERSION) != 0) return fail("library and headers disagree on the version");
#ifdef EXPECTED_VERSION
  if (std::strcmp(retroaa::version(), EXPECTED_VERSION) != 0) return fail("not the version the package announced");
#endif
  if (!makeContext()) return fail("no EGL OpenGL 4.5 core context");
  const int width = 32, height = 24;
  retroaa::GBufferLayout layout;
  layout.width = width, layout.height = height;
  layout.attachments = {{retroaa::AttachmentRole::Albedo, GL_RGBA8, texture(GL_RGBA8, width, height)},
                        {retroaa::AttachmentRole::ViewPosition, GL_RGBA16F, texture(GL_RGBA16F, width, height)},
                        {retroaa::AttachmentRole::NormalGloss, GL_RGBA16F, texture(GL_RGBA16F, width, height)}};
  layout.depthStencilTexture = texture(GL_DEPTH24_STENCIL8, width, height);
  layout.gbufferFramebuffer = framebuffer(layout.attachments[0].texture, layout.depthStencilTexture);
  layout.lightTexture = texture(GL_RGBA16F, width, height);
  layout.lightFramebuffer = framebuffer(layout.lightTexture);
  layout.displayTexture = texture(GL_RGBA8, width, height);
  layout.displayFramebuffer = framebuffer(layout.displayTexture);

  retroaa::Description description;
  description.layout = layout;
  // The embedded presets: `low` is reconstruct (presets/low.cfg), so the frame includes its prepass.
  if (!retroaa::applySetting(description.config, "preset", "low")) return fail("no embedded preset 'low'");
  if (description.config.method != retroaa::Method::Reconstruct) return fail("preset 'low' changed");
  auto created = retroaa::Plugin::create(description);
  if (!created) return fail(created.error().message.c_str());
  retroaa::Plugin& plugin = *created.value();

  // The model pass: cleared to one surface 10 m away (a real engine draws its models here).
  glBindFramebuffer(GL_FRAMEBUFFER, plugin.geometryFramebuffer());
  const GLfloat albedo[] = {0.5f, 0.5f, 0.5f, 1}, position[] = {0, 0, 10, 1}, normal[] = {0, 0, 1, 0.5f};
  glClearBufferfv(GL_COLOR, 0, albedo);
  glClearBufferfv(GL_COLOR, 1, position);
  glClearBufferfv(GL_COLOR, 2, normal);
  glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0);
  if (plugin.prepassFramebuffer() == 0) return fail("reconstruct hands out no prepass framebuffer");
  glBindFramebuffer(GL_FRAMEBUFFER, plugin.prepassFramebuffer());  // the models again: depth and normal
  glClearBufferfv(GL_COLOR, 2, normal);
  glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0);
  if (!plugin.resolve({})) return fail("resolve");
  int lightingCalls = 0;
  const retroaa::Status shaded = plugin.shade([&lightingCalls](retroaa::GLuintHandle target) {
    ++lightingCalls;
    const GLfloat light[] = {0.25f, 0.5f, 0.75f, 1};
    glClearNamedFramebufferfv(target, GL_COLOR, 0, light);
  });
  if (!shaded || lightingCalls != 1) return fail("shade");
  if (!plugin.post()) return fail("post");
  const retroaa::Stats stats = plugin.waitForStats();
  if (stats.lightingEvaluations != uint64_t(width) * height) return fail("not one lighting evaluation per pixel");
  if (glGetError() != GL_NO_ERROR) return fail("a GL error");
  std::printf(
      "consumer: retroaa %s, preset low (%s) at %d samples, %.3f evaluations per pixel, %d GL objects, no GL "
      "error\n",
      retroaa::version(), retroaa::toString(stats.method), stats.samples, stats.evaluationsPerPixel(),
      stats.glObjectsHeld);
  return 0;
}
