// A third party's deferred renderer, shaped like LearnOpenGL's "Deferred Shading" chapter: world-space
// positions and normals, an unsized GL_DEPTH_COMPONENT renderbuffer, lighting straight into the window,
// then the G-buffer's depth blitted into the window for a forward pass (the lights' cubes). Below it,
// everything it takes to put retroaa into it (docs/integration.md shows the same lines, and run.sh
// checks that they agree and counts them): the glue between its markers, and the lines marked
// `// retroaa` in frameWithRetroaa(), the renderer's frame with its calls.
//
// The window is an EGL pbuffer: a real default framebuffer, headless; it holds linear values. Run with
// method specs (`window_lit fxaa resolve+temporal`), or with none for every method of retroaa's registry;
// each is checked against the renderer's frame at 4x4 (docs/integration.md lists the checks): no GL error,
// `off` byte for byte the renderer without retroaa, the forward pass drawn where it is seen and hidden where
// it is not, anti-aliased by the multisampled G-buffer, spread by no post filter, and the models' edges at
// least as good as without retroaa.
#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <retroaa/plugin.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace {

// ---------------------------------------------------------------- the third party's renderer

struct Mat4 {
  float m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  // column-major
};
Mat4 operator*(const Mat4& a, const Mat4& b) {
  Mat4 r;
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row) {
      r.m[c * 4 + row] = 0;
      for (int k = 0; k < 4; ++k) r.m[c * 4 + row] += a.m[k * 4 + row] * b.m[c * 4 + k];
    }
  return r;
}
Mat4 perspective(float fovY, float aspect, float near, float far) {
  Mat4 p;
  const float f = 1 / std::tan(fovY / 2);
  p.m[0] = f / aspect, p.m[5] = f, p.m[10] = (far + near) / (near - far), p.m[11] = -1;
  p.m[14] = 2 * far * near / (near - far), p.m[15] = 0;
  return p;
}
Mat4 lookAt(const float eye[3], const float centre[3]) {  // up = +y
  float f[3] = {centre[0] - eye[0], centre[1] - eye[1], centre[2] - eye[2]};
  const float fl = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
  for (float& v : f) v /= fl;
  float s[3] = {-f[2], 0, f[0]};  // f × up
  const float sl = std::sqrt(s[0] * s[0] + s[2] * s[2]);
  s[0] /= sl, s[2] /= sl;
  const float u[3] = {s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2], s[0] * f[1] - s[1] * f[0]};
  Mat4 v;
  for (int i = 0; i < 3; ++i) v.m[i * 4] = s[i], v.m[i * 4 + 1] = u[i], v.m[i * 4 + 2] = -f[i];
  v.m[12] = -(s[0] * eye[0] + s[1] * eye[1] + s[2] * eye[2]);
  v.m[13] = -(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]);
  v.m[14] = f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2];
  return v;
}
Mat4 placed(float x, float y, float z, float yawDegrees, float sx, float sy, float sz) {
  const float c = std::cos(yawDegrees * 3.14159265f / 180), s = std::sin(yawDegrees * 3.14159265f / 180);
  Mat4 m;
  m.m[0] = c * sx, m.m[2] = -s * sx, m.m[5] = sy, m.m[8] = s * sz, m.m[10] = c * sz;
  m.m[12] = x, m.m[13] = y, m.m[14] = z;
  return m;
}

const char* kGeometryVertex = R"(#version 450 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 model, viewProjection;
out vec3 worldPosition, worldNormal;
void main() {
  worldPosition = (model * vec4(position, 1)).xyz;
  worldNormal = mat3(model) * normal;  // axis-aligned scales only
  gl_Position = viewProjection * vec4(worldPosition, 1);
})";
const char* kGeometryFragment = R"(#version 450 core
in vec3 worldPosition, worldNormal;
uniform vec3 albedo;
layout(location = 0) out vec4 gPosition;
layout(location = 1) out vec4 gNormal;
layout(location = 2) out vec4 gAlbedoSpecular;
void main() {
  gPosition = vec4(worldPosition, 1);
  gNormal = vec4(normalize(worldNormal), 0);
  float checker = mod(floor(worldPosition.x * 2) + floor(worldPosition.z * 2), 2);
  gAlbedoSpecular = vec4(albedo * (0.6 + 0.4 * checker), 0.5);
})";
const char* kFullScreenVertex = R"(#version 450 core
void main() { gl_Position = vec4(vec2(gl_VertexID & 1, gl_VertexID >> 1) * 4 - 1, 0, 1); })";
const char* kLightingFragment = R"(#version 450 core
layout(binding = 0) uniform sampler2D gPosition;
layout(binding = 1) uniform sampler2D gNormal;
layout(binding = 2) uniform sampler2D gAlbedoSpecular;
uniform vec3 eye, lightPositions[2], lightColours[2];
out vec4 colour;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec3 normal = texelFetch(gNormal, pixel, 0).xyz;
  if (dot(normal, normal) < 1e-6) { colour = vec4(0.05, 0.06, 0.09, 1); return; }  // cleared: no geometry
  vec3 position = texelFetch(gPosition, pixel, 0).xyz;
  vec4 albedoSpecular = texelFetch(gAlbedoSpecular, pixel, 0);
  vec3 n = normalize(normal), toEye = normalize(eye - position), radiance = 0.08 * albedoSpecular.rgb;
  for (int i = 0; i < 2; ++i) {
    vec3 toLight = lightPositions[i] - position;
    float attenuation = 8 / (1 + dot(toLight, toLight));
    toLight = normalize(toLight);
    float specular = pow(max(dot(n, normalize(toLight + toEye)), 0), 32) * albedoSpecular.a;
    radiance += lightColours[i] * attenuation * (max(dot(n, toLight), 0) * albedoSpecular.rgb + specular);
  }
  colour = vec4(radiance / (1 + radiance), 1);
})";
const char* kForwardFragment = R"(#version 450 core
uniform vec3 albedo;
out vec4 colour;
void main() { colour = vec4(albedo, 1); })";

GLuint program(const char* vertex, const char* fragment) {
  const GLuint name = glCreateProgram();
  for (const auto& [type, source] : {std::pair{GL_VERTEX_SHADER, vertex}, std::pair{GL_FRAGMENT_SHADER, fragment}}) {
    const GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    glAttachShader(name, shader);
    glDeleteShader(shader);
  }
  glLinkProgram(name);
  GLint linked = 0;
  glGetProgramiv(name, GL_LINK_STATUS, &linked);
  if (!linked) std::fprintf(stderr, "window_lit: a shader does not link\n"), std::exit(1);
  return name;
}

struct GBuffer {
  int width = 0, height = 0;
  GLuint framebuffer = 0, position = 0, normal = 0, albedoSpecular = 0, depth = 0;
};

struct Object {
  Mat4 model;
  float albedo[3];
};

class Renderer {
 public:
  static constexpr float kFovY = 0.9f, kNear = 0.1f, kFar = 50.0f;
  GBuffer gbuffer;
  float eye[3] = {0, 3, 6}, lightPositions[2][3] = {{0.2f, 1.4f, 2.2f}, {0.75f, 1.0f, -1.5f}};
  const float lightColours[2][3] = {{1.0f, 0.9f, 0.2f}, {0.2f, 0.6f, 1.0f}};
  bool lightsShown = true;  // the forward pass's cubes (the check compares frames without them)

  Renderer(int width, int height) {
    gbuffer.width = width, gbuffer.height = height;
    const auto texture = [&](GLenum format) {
      GLuint name = 0;
      glCreateTextures(GL_TEXTURE_2D, 1, &name);
      glTextureStorage2D(name, 1, format, width, height);
      return name;
    };
    gbuffer.position = texture(GL_RGBA16F), gbuffer.normal = texture(GL_RGBA16F);
    gbuffer.albedoSpecular = texture(GL_RGBA8);
    glCreateRenderbuffers(1, &gbuffer.depth);
    glNamedRenderbufferStorage(gbuffer.depth, GL_DEPTH_COMPONENT, width, height);
    glCreateFramebuffers(1, &gbuffer.framebuffer);
    const GLuint attachments[] = {gbuffer.position, gbuffer.normal, gbuffer.albedoSpecular};
    const GLenum drawBuffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    for (int i = 0; i < 3; ++i) glNamedFramebufferTexture(gbuffer.framebuffer, drawBuffers[i], attachments[i], 0);
    glNamedFramebufferDrawBuffers(gbuffer.framebuffer, 3, drawBuffers);
    glNamedFramebufferRenderbuffer(gbuffer.framebuffer, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, gbuffer.depth);
    geometryProgram_ = program(kGeometryVertex, kGeometryFragment);
    lightingProgram_ = program(kFullScreenVertex, kLightingFragment);
    forwardProgram_ = program(kGeometryVertex, kForwardFragment);
    createCube();
    objects_ = {{placed(0, -0.05f, 0, 0, 8, 0.1f, 8), {0.5f, 0.5f, 0.45f}},
                {placed(-1.5f, 0.5f, 0, 30, 1, 1, 1), {0.8f, 0.3f, 0.2f}},
                {placed(0.8f, 0.6f, -0.5f, 65, 1, 1.2f, 1), {0.3f, 0.7f, 0.3f}},
                {placed(-0.1f, 0.35f, 1.3f, 10, 0.7f, 0.7f, 0.7f), {0.7f, 0.7f, 0.8f}}};
  }
  ~Renderer() {
    const GLuint textures[] = {gbuffer.position, gbuffer.normal, gbuffer.albedoSpecular};
    glDeleteTextures(3, textures);
    glDeleteRenderbuffers(1, &gbuffer.depth);
    glDeleteFramebuffers(1, &gbuffer.framebuffer);
    glDeleteBuffers(1, &cubeBuffer_);
    glDeleteVertexArrays(1, &cubeArray_);
    for (GLuint name : {geometryProgram_, lightingProgram_, forwardProgram_}) glDeleteProgram(name);
  }
  Mat4 view() const {
    const float centre[3] = {0, 0.5f, 0};
    return lookAt(eye, centre);
  }
  Mat4 projection() const { return perspective(kFovY, float(gbuffer.width) / gbuffer.height, kNear, kFar); }

  // ---------------------------------------------- retroaa call sites: begin
  void frameWithoutRetroaa() {  // the renderer as its authors wrote it
    const Mat4 viewProjection = projection() * view();
    geometryPass(gbuffer.framebuffer, 1, viewProjection);
    lightingPass(0);
    blitDepth(0);
    forwardPass(0, viewProjection);
  }

  template <typename Retroaa>
  void frameWithRetroaa(Retroaa& aa) {
    Mat4 projection = this->projection();
    aa.jitter(projection);  // retroaa
    const Mat4 viewProjection = projection * view();
    geometryPass(aa.plugin->geometryFramebuffer(), aa.plugin->geometryScale(), viewProjection);    // retroaa
    const auto drawModelsAgain = [&](GLuint target) { geometryPass(target, 1, viewProjection); };  // retroaa
    aa.resolve(*this, drawModelsAgain);                                                            // retroaa
    aa.check(aa.plugin->shade([&](GLuint target) { lightingPass(target); }));                      // retroaa
    forwardPass(aa.beginForward(gbuffer), viewProjection);                                         // retroaa
    aa.present();                                                                                  // retroaa
  }
  // ---------------------------------------------- retroaa call sites: end

  void geometryPass(GLuint target, int scale, const Mat4& viewProjection) {
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, gbuffer.width * scale, gbuffer.height * scale);
    glEnable(GL_DEPTH_TEST);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(geometryProgram_);
    glUniformMatrix4fv(glGetUniformLocation(geometryProgram_, "viewProjection"), 1, GL_FALSE, viewProjection.m);
    glBindVertexArray(cubeArray_);
    for (const Object& object : objects_) {
      glUniformMatrix4fv(glGetUniformLocation(geometryProgram_, "model"), 1, GL_FALSE, object.model.m);
      glUniform3fv(glGetUniformLocation(geometryProgram_, "albedo"), 1, object.albedo);
      glDrawArrays(GL_TRIANGLES, 0, 36);
    }
    glViewport(0, 0, gbuffer.width, gbuffer.height);
  }

  void lightingPass(GLuint target) {
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(lightingProgram_);
    glUniform3fv(glGetUniformLocation(lightingProgram_, "eye"), 1, eye);
    glUniform3fv(glGetUniformLocation(lightingProgram_, "lightPositions"), 2, lightPositions[0]);
    glUniform3fv(glGetUniformLocation(lightingProgram_, "lightColours"), 2, lightColours[0]);
    const GLuint textures[] = {gbuffer.position, gbuffer.normal, gbuffer.albedoSpecular};
    glBindTextures(0, 3, textures);
    glBindVertexArray(cubeArray_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }

  void blitDepth(GLuint target) {  // the G-buffer's depth, for the forward pass to test against
    const int w = gbuffer.width, h = gbuffer.height;
    glBlitNamedFramebuffer(gbuffer.framebuffer, target, 0, 0, w, h, 0, 0, w, h, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  }

  void forwardPass(GLuint target, const Mat4& viewProjection) {  // the lights' cubes, over the lit scene
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    if (!lightsShown) return;
    glEnable(GL_DEPTH_TEST);
    glUseProgram(forwardProgram_);
    glUniformMatrix4fv(glGetUniformLocation(forwardProgram_, "viewProjection"), 1, GL_FALSE, viewProjection.m);
    glBindVertexArray(cubeArray_);
    for (int i = 0; i < 2; ++i) {
      const float* p = lightPositions[i];
      const Mat4 model = placed(p[0], p[1], p[2], 0, 0.25f, 0.25f, 0.25f);
      glUniformMatrix4fv(glGetUniformLocation(forwardProgram_, "model"), 1, GL_FALSE, model.m);
      glUniform3fv(glGetUniformLocation(forwardProgram_, "albedo"), 1, lightColours[i]);
      glDrawArrays(GL_TRIANGLES, 0, 36);
    }
  }

 private:
  void createCube() {  // 36 vertices: position, normal
    std::vector<float> vertices;
    for (int axis = 0; axis < 3; ++axis)
      for (float sign : {-1.0f, 1.0f}) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        const float corners[6][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};
        for (int k = 0; k < 6; ++k) {
          const int c = sign > 0 ? k : 5 - k;  // counter-clockwise seen from outside
          float vertex[6] = {};
          vertex[axis] = 0.5f * sign, vertex[u] = 0.5f * corners[c][0], vertex[v] = 0.5f * corners[c][1];
          vertex[3 + axis] = sign;
          vertices.insert(vertices.end(), vertex, vertex + 6);
        }
      }
    glCreateBuffers(1, &cubeBuffer_);
    glNamedBufferStorage(cubeBuffer_, GLsizeiptr(vertices.size() * sizeof(float)), vertices.data(), 0);
    glCreateVertexArrays(1, &cubeArray_);
    glVertexArrayVertexBuffer(cubeArray_, 0, cubeBuffer_, 0, 6 * sizeof(float));
    for (GLuint attribute : {0u, 1u}) {
      glEnableVertexArrayAttrib(cubeArray_, attribute);
      glVertexArrayAttribFormat(cubeArray_, attribute, 3, GL_FLOAT, GL_FALSE, attribute * 3 * sizeof(float));
      glVertexArrayAttribBinding(cubeArray_, attribute, 0);
    }
  }

  GLuint geometryProgram_ = 0, lightingProgram_ = 0, forwardProgram_ = 0, cubeBuffer_ = 0, cubeArray_ = 0;
  std::vector<Object> objects_;
};

// ---------------------------------------------------------------- retroaa glue: begin
// The window cannot be filtered in place, so the glue gives the renderer a window of its own (colour,
// and depth in the G-buffer's depth format, as the renderer's depth blit needs) and presents it after post().
struct RetroaaGlue {
  std::unique_ptr<retroaa::Plugin> plugin;
  GLuint display = 0, displayDepth = 0, window = 0;
  int width = 0, height = 0;

  bool create(const GBuffer& g) {  // `off` until select()
    glCreateTextures(GL_TEXTURE_2D, 1, &display);
    glTextureStorage2D(display, 1, GL_RGBA8, width = g.width, height = g.height);  // the window's format
    glCreateRenderbuffers(1, &displayDepth);
    glNamedRenderbufferStorage(displayDepth, GL_DEPTH_COMPONENT, width, height);  // as the G-buffer's: blits
    glCreateFramebuffers(1, &window);
    glNamedFramebufferTexture(window, GL_COLOR_ATTACHMENT0, display, 0);
    glNamedFramebufferRenderbuffer(window, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, displayDepth);
    retroaa::Description d;
    d.layout.width = width, d.layout.height = height;
    d.layout.attachments = {{retroaa::AttachmentRole::ViewPosition, GL_RGBA16F, g.position},
                            {retroaa::AttachmentRole::NormalGloss, GL_RGBA16F, g.normal},
                            {retroaa::AttachmentRole::Albedo, GL_RGBA8, g.albedoSpecular}};
    d.layout.depthSource = retroaa::DepthSource::WorldPosition;
    d.layout.gbufferFramebuffer = g.framebuffer, d.layout.depthStencilRenderbuffer = g.depth;
    d.layout.lightFramebuffer = d.layout.displayFramebuffer = window;
    d.layout.lightTexture = d.layout.displayTexture = display;
    d.layout.drawsForwardPasses = true, d.layout.displayEncoding = retroaa::DisplayEncoding::Linear;  // no sRGB
    d.log = [](retroaa::LogLevel, const std::string& m) { std::fprintf(stderr, "retroaa: %s\n", m.c_str()); };
    auto created = retroaa::Plugin::create(d);
    if (created) plugin = std::move(created.value());
    return check(created ? retroaa::Status() : retroaa::Status(created.error()));
  }
  ~RetroaaGlue() {
    plugin.reset();
    glDeleteFramebuffers(1, &window), glDeleteRenderbuffers(1, &displayDepth), glDeleteTextures(1, &display);
  }
  bool select(const std::string& spec) {  // a method spec: `fxaa`, `resolve+temporal`, `ssaa@supersample=2`
    retroaa::Config config;
    return check(retroaa::applyMethodSpec(config, spec)) && check(plugin->reconfigure(config));
  }
  void jitter(Mat4& projection) const {
    projection.m[8] += 2 * plugin->jitter().x / width, projection.m[9] += 2 * plugin->jitter().y / height;
  }
  void resolve(const Renderer& r, const std::function<void(GLuint)>& drawModelsAgain) {
    retroaa::FrameInfo frame{Renderer::kFovY, Renderer::kNear, Renderer::kFar};
    std::memcpy(frame.viewMatrix, r.view().m, 64), std::memcpy(frame.projectionMatrix, r.projection().m, 64);
    check(plugin->resolve(frame));
    if (const GLuint target = plugin->prepassFramebuffer()) drawModelsAgain(target);  // coverage, reconstruct
  }
  GLuint beginForward(const GBuffer& g) {  // multisampled over the G-buffer's depth, or the window: depth blitted
    const retroaa::Result<retroaa::GLuintHandle> target = plugin->beginForward();
    if (target && target.value() != window) return target.value();
    check(target ? retroaa::Status() : retroaa::Status(target.error()));
    glBlitNamedFramebuffer(g.framebuffer, window, 0, 0, width, height, 0, 0, width, height, GL_DEPTH_BUFFER_BIT,
                           GL_NEAREST);
    return window;
  }
  void present() {
    check(plugin->endForward());
    check(plugin->post());
    glBlitNamedFramebuffer(window, 0, 0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  static bool check(const retroaa::Status& status) {
    if (!status) std::fprintf(stderr, "retroaa: %s\n", status.error().message.c_str());
    return bool(status);
  }
};
// ---------------------------------------------------------------- retroaa glue: end

// ---------------------------------------------------------------- the check

bool makeWindow(int width, int height) {  // an EGL pbuffer: the default framebuffer, headless
  const EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr) || !eglBindAPI(EGL_OPENGL_API))
    return false;
  const EGLint configAttributes[] = {EGL_SURFACE_TYPE,
                                     EGL_PBUFFER_BIT,
                                     EGL_RENDERABLE_TYPE,
                                     EGL_OPENGL_BIT,
                                     EGL_RED_SIZE,
                                     8,
                                     EGL_GREEN_SIZE,
                                     8,
                                     EGL_BLUE_SIZE,
                                     8,
                                     EGL_DEPTH_SIZE,
                                     24,
                                     EGL_NONE};
  EGLConfig configs[64], config = nullptr;
  EGLint count = 0, red = 0;  // eglChooseConfig lists deeper colour first: take an 8-bit one, as windows are
  eglChooseConfig(display, configAttributes, configs, 64, &count);
  for (EGLint i = 0; i < count && !config; ++i)
    if (eglGetConfigAttrib(display, configs[i], EGL_RED_SIZE, &red) && red == 8) config = configs[i];
  if (!config) return false;
  const EGLint surfaceAttributes[] = {EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE};
  const EGLSurface surface = eglCreatePbufferSurface(display, config, surfaceAttributes);
  const EGLint contextAttributes[] = {
      EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  const EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
  return surface != EGL_NO_SURFACE && context != EGL_NO_CONTEXT && eglMakeCurrent(display, surface, surface, context);
}

std::vector<uint8_t> readWindow(int width, int height) {
  std::vector<uint8_t> pixels(size_t(width) * height * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  return pixels;
}

// Where a world point lands in the window (pixel, bottom-up), for the forward pass's checks.
void project(const Mat4& viewProjection, const float p[3], int width, int height, int& x, int& y) {
  float clip[4];
  for (int row = 0; row < 4; ++row)
    clip[row] = viewProjection.m[row] * p[0] + viewProjection.m[4 + row] * p[1] + viewProjection.m[8 + row] * p[2] +
                viewProjection.m[12 + row];
  x = int((clip[0] / clip[3] * 0.5f + 0.5f) * width), y = int((clip[1] / clip[3] * 0.5f + 0.5f) * height);
}

// The window's pixels in three kinds, from the renderer's own frame at 4× width and height (its 4×4 blocks):
// the forward pass's edges (blocks part cube, part scene), the models' edges (no cube; a depth step within the
// block), and the scene around the cubes (no cube, within 6 pixels of one). The reference is the blocks' mean.
struct Reference {
  std::vector<double> colour;  // rgb per pixel, stored values (the display is linear: means as stored)
  std::vector<uint8_t> forwardEdge, modelEdge, nearForward;
};

Reference referenceFrame(int width, int height, const float (&cubeColours)[2][3]) {
  constexpr int kScale = 4;
  Renderer big(width * kScale, height * kScale);
  big.frameWithoutRetroaa();
  const std::vector<uint8_t> image = readWindow(width * kScale, height * kScale);
  std::vector<float> depth(image.size() / 4);
  glReadPixels(0, 0, width * kScale, height * kScale, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  Reference r;
  r.colour.assign(size_t(width) * height * 3, 0.0);
  r.forwardEdge.assign(size_t(width) * height, 0), r.modelEdge = r.nearForward = r.forwardEdge;
  std::vector<int> cubes(size_t(width) * height, 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t pixel = size_t(y) * width + x;
      float nearest = 1e9f, farthest = 0;
      for (int j = 0; j < kScale; ++j)
        for (int i = 0; i < kScale; ++i) {
          const size_t sub = size_t(y * kScale + j) * width * kScale + x * kScale + i;
          bool cube = false;
          for (const auto& c : cubeColours) {
            int distance = 0;
            for (int k = 0; k < 3; ++k) distance += std::abs(image[sub * 4 + k] - int(std::lround(c[k] * 255)));
            cube = cube || distance <= 3;
          }
          cubes[pixel] += cube;
          for (int k = 0; k < 3; ++k) r.colour[pixel * 3 + k] += image[sub * 4 + k] / double(kScale * kScale);
          const float n = Renderer::kNear, f = Renderer::kFar;  // window depth to metres
          const float metres = depth[sub] >= 1.0f ? 1e6f : 2 * n * f / (f + n - (2 * depth[sub] - 1) * (f - n));
          nearest = std::min(nearest, metres), farthest = std::max(farthest, metres);
        }
      r.forwardEdge[pixel] = cubes[pixel] > 0 && cubes[pixel] < kScale * kScale;
      r.modelEdge[pixel] = cubes[pixel] == 0 && farthest > nearest * 1.05f;
    }
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int j = std::max(0, y - 6); j <= std::min(height - 1, y + 6) && cubes[size_t(y) * width + x] == 0; ++j)
        for (int i = std::max(0, x - 6); i <= std::min(width - 1, x + 6); ++i)
          r.nearForward[size_t(y) * width + x] |= cubes[size_t(j) * width + i] > 0;
  return r;
}

// PSNR (dB, stored values) of `image` against the reference over the pixels `where` marks.
double psnr(const std::vector<uint8_t>& image, const Reference& r, const std::vector<uint8_t>& where) {
  double sum = 0;
  size_t count = 0;
  for (size_t pixel = 0; pixel < where.size(); ++pixel)
    for (int k = 0; k < 3 && where[pixel]; ++k, ++count) {
      const double e = image[pixel * 4 + k] - r.colour[pixel * 3 + k];
      sum += e * e;
    }
  return count == 0 ? 0 : 10 * std::log10(255.0 * 255.0 / std::max(sum / double(count), 1e-12));
}

// The method a spec names first (`resolve` of `resolve+fxaa@samples=8`).
std::string baseMethod(const std::string& spec) { return spec.substr(0, spec.find_first_of("+@")); }

}  // namespace

int main(int argc, char** argv) {
  const int width = 192, height = 144;
  // The window holds the reference at 4× too; the renderer draws in its lower-left corner.
  if (!makeWindow(width * 4, height * 4))
    return std::fprintf(stderr, "window_lit: no EGL pbuffer with GL 4.5 core\n"), 1;
  std::vector<std::string> specs(argv + 1, argv + argc);
  if (specs.empty())
    for (const retroaa::MethodInfo& method : retroaa::methodTable()) specs.push_back(method.name);

  Renderer renderer(width, height);
  const Reference reference = referenceFrame(width, height, renderer.lightColours);
  renderer.lightsShown = false;
  renderer.frameWithoutRetroaa();
  const std::vector<uint8_t> stockWithoutLights = readWindow(width, height);
  renderer.lightsShown = true;
  renderer.frameWithoutRetroaa();
  const std::vector<uint8_t> stock = readWindow(width, height);
  const double stockForward = psnr(stock, reference, reference.forwardEdge);
  const double stockModel = psnr(stock, reference, reference.modelEdge);
  const double stockNear = psnr(stock, reference, reference.nearForward);
  int lightPixel[2][2];
  for (int i = 0; i < 2; ++i)
    project(renderer.projection() * renderer.view(), renderer.lightPositions[i], width, height, lightPixel[i][0],
            lightPixel[i][1]);

  RetroaaGlue aa;
  if (!aa.create(renderer.gbuffer)) return 1;
  int failures = 0;
  std::printf(
      "PSNR in dB against the renderer at 4x4, on the forward pass's edges, the models' edges and the scene "
      "within 6 px of the forward pass\n%-22s %8s %10s %12s %9s %9s %9s\n",
      "method", "changed", "evals/px", "plugin MiB", "forward", "models", "near fwd");
  std::printf("%-22s %8s %10s %12s %9.2f %9.2f %9.2f\n", "(without retroaa)", "", "", "", stockForward, stockModel,
              stockNear);
  const auto render = [&](bool lightsShown) {
    renderer.lightsShown = lightsShown;
    for (int frame = 0; frame < 16; ++frame) renderer.frameWithRetroaa(aa);  // `temporal` converges
    return readWindow(width, height);
  };
  for (const std::string& spec : specs) {
    if (!aa.select(spec)) return 1;
    // The post filters that rebuild pixels from the opaque surfaces' depth (coverage, reconstruct; alone: a
    // stacked temporal, fxaa or smaa filters the cubes' edges as it should) draw the forward pass into the window
    // as the renderer does: outside the pixels it covers there, nothing of the cubes may spread into the scene.
    const bool filtersAfterForward =
        (baseMethod(spec) == "coverage" || baseMethod(spec) == "reconstruct") && spec.find('+') == std::string::npos;
    const std::vector<uint8_t> withoutLights = filtersAfterForward ? render(false) : std::vector<uint8_t>();
    const std::vector<uint8_t> image = render(true);
    const retroaa::Stats stats = aa.plugin->waitForStats();
    size_t changed = 0;  // pixels more than 8/255 from the renderer without retroaa
    for (size_t i = 0; i < image.size(); i += 4)
      for (size_t c = 0; c < 3; ++c) {
        if (std::abs(int(image[i + c]) - int(stock[i + c])) > 8) {
          ++changed;
          break;
        }
      }
    const auto failed = [&](const char* what) {
      std::fprintf(stderr, "window_lit: %s: %s\n", spec.c_str(), what);
      ++failures;
    };
    if (glGetError() != GL_NO_ERROR) failed("a GL error");
    if (spec == "off" && image != stock) failed("`off` is not the renderer without retroaa, byte for byte");
    if (spec != "off" && (changed == 0 || changed * 6 > size_t(width) * height))
      failed("changed no pixel, or more than a sixth of them");
    for (int i = 0; i < 2; ++i) {  // light 0 in view; light 1's centre behind the green cube
      const uint8_t* pixel = &image[(size_t(lightPixel[i][1]) * width + lightPixel[i][0]) * 4];
      int distance = 0;
      for (int c = 0; c < 3; ++c) distance += std::abs(pixel[c] - int(std::lround(renderer.lightColours[i][c] * 255)));
      if ((i == 0) != (distance <= 6))
        failed(i == 0 ? "the forward pass is missing" : "the forward pass shows through");
    }
    const double forward = psnr(image, reference, reference.forwardEdge);
    const double models = psnr(image, reference, reference.modelEdge);
    const double nearForward = psnr(image, reference, reference.nearForward);
    // Pixels outside the cubes' own that the cubes changed to something else than unfiltered (where a pixel's
    // filter would read a cube, it is left as the renderer drew it).
    int spread = 0;
    for (size_t i = 0; filtersAfterForward && i < image.size(); i += 4)
      for (size_t c = 0; c < 3 && std::memcmp(&stock[i], &stockWithoutLights[i], 3) == 0; ++c)
        if (std::abs(int(image[i + c]) - int(withoutLights[i + c])) > 1 && std::abs(image[i + c] - stock[i + c]) > 1) {
          ++spread;
          break;
        }
    if (spread > 0) failed("the forward pass's colour spread into pixels it does not cover");
    // The multisampled G-buffer's methods draw the forward pass multisampled (ssaa's supersampled one does not).
    const std::string base = baseMethod(spec);
    const bool multisamplesForward = base == "resolve" || base == "edge" || base == "adaptive" || base == "aggregate" ||
                                     base == "per-sample" || base == "smaa-s2x";
    if (multisamplesForward && forward < stockForward + 6) failed("the forward pass's edges are not anti-aliased");
    if (models < stockModel - 0.1) failed("the models' edges are worse than without retroaa");
    std::printf("%-22s %8zu %10.3f %12.2f %9.2f %9.2f %9.2f%s\n", spec.c_str(), changed, stats.evaluationsPerPixel(),
                stats.bytesHeld / 1048576.0, forward, models, nearForward,
                filtersAfterForward ? (" spread " + std::to_string(spread) + " px").c_str() : "");
  }
  if (failures) return 1;
  std::printf("window_lit: %zu methods, each checked\n", specs.size());
  return 0;
}
