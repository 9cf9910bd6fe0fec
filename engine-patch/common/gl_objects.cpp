#include "gl_objects.h"

#include "gl_basics.h"

#include <map>
#include <sstream>

namespace host {

namespace {

std::string expandIncludes(const std::string& file, int depth = 0) {
  const auto& files = embeddedFiles();
  const auto found = files.find(file);
  if (found == files.end()) throw std::runtime_error("host shader not embedded: " + file);
  if (depth > 8) throw std::runtime_error("host shader includes nest too deep: " + file);
  std::istringstream in(found->second);
  std::string line, out;
  while (std::getline(in, line)) {
    const std::string directive = "#include \"";
    if (line.rfind(directive, 0) == 0) {
      const std::string name = line.substr(directive.size(), line.find('"', directive.size()) - directive.size());
      out += expandIncludes("shaders/" + name, depth + 1);
    } else {
      out += line + "\n";
    }
  }
  return out;
}

GLuint compile(GLenum stage, const std::string& file, const std::string& defines) {
  std::string source = expandIncludes(file);
  const size_t versionEnd = source.find('\n');
  if (!defines.empty() && source.rfind("#version", 0) == 0) source.insert(versionEnd + 1, defines);
  std::string log;
  const GLuint shader = gl_basics::compileStage(stage, source, log);
  if (!shader) throw std::runtime_error("host shader " + file + " does not compile:\n" + log);
  return shader;
}

}  // namespace

Program::Program(const std::string& vertexFile, const std::string& fragmentFile, const std::string& defines) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertexFile, defines);
  const GLuint fs = compile(GL_FRAGMENT_SHADER, fragmentFile, defines);
  name_ = glCreateProgram();
  glAttachShader(name_, vs);
  glAttachShader(name_, fs);
  glLinkProgram(name_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(name_, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096];
    glGetProgramInfoLog(name_, sizeof log, nullptr, log);
    throw std::runtime_error("host program " + vertexFile + " + " + fragmentFile + " does not link:\n" + log);
  }
  const std::string label = fragmentFile;
  glObjectLabel(GL_PROGRAM, name_, -1, label.c_str());
}

Program::~Program() {
  if (name_) glDeleteProgram(name_);
}

Program& Program::operator=(Program&& other) noexcept {
  if (this != &other) {
    if (name_) glDeleteProgram(name_);
    name_ = std::exchange(other.name_, 0);
  }
  return *this;
}

uint64_t texelBytes(GLenum format) {
  switch (format) {
    case GL_RGBA32F: return 16;
    case GL_RGBA16F: return 8;
    case GL_RGBA8:
    case GL_SRGB8_ALPHA8:
    case GL_RG16F:
    case GL_DEPTH24_STENCIL8:
    case GL_DEPTH_COMPONENT32F: return 4;
    default: return 0;
  }
}

Texture makeTexture2D(GLenum internalFormat, int width, int height, const char* label) {
  const GLuint name = gl_basics::createTexelTexture2D(internalFormat, width, height);
  glObjectLabel(GL_TEXTURE, name, -1, label);
  return Texture(name);
}

void checkFramebuffer(GLuint framebuffer, const char* label) {
  const GLenum status = glCheckNamedFramebufferStatus(framebuffer, GL_FRAMEBUFFER);
  if (status == GL_FRAMEBUFFER_COMPLETE) return;
  std::ostringstream message;
  message << "host framebuffer '" << label << "' is incomplete (status 0x" << std::hex << status << ")";
  throw std::runtime_error(message.str());
}

GpuMesh uploadMesh(const Mesh& mesh) {
  GpuMesh gpu;
  GLuint names[2];
  glCreateBuffers(2, names);
  gpu.vertices = Buffer(names[0]);
  gpu.indices = Buffer(names[1]);
  glNamedBufferStorage(gpu.vertices, mesh.vertices.size() * sizeof(Vertex), mesh.vertices.data(), 0);
  glNamedBufferStorage(gpu.indices, mesh.indices.size() * sizeof(uint32_t), mesh.indices.data(), 0);
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  gpu.vertexArray = VertexArray(vao);
  glVertexArrayVertexBuffer(vao, 0, gpu.vertices, 0, sizeof(Vertex));
  glVertexArrayElementBuffer(vao, gpu.indices);
  const struct {
    GLint components;
    size_t offset;
  } attributes[] = {{3, offsetof(Vertex, position)},
                    {3, offsetof(Vertex, normal)},
                    {2, offsetof(Vertex, uv)},
                    {4, offsetof(Vertex, tangent)}};
  for (GLuint a = 0; a < 4; ++a) {
    glEnableVertexArrayAttrib(vao, a);
    glVertexArrayAttribFormat(vao, a, attributes[a].components, GL_FLOAT, GL_FALSE, GLuint(attributes[a].offset));
    glVertexArrayAttribBinding(vao, a, 0);
  }
  gpu.indexCount = static_cast<GLsizei>(mesh.indices.size());
  return gpu;
}

}  // namespace host
