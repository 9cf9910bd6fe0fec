#include "shader_library.h"

#include "context.h"
#include "gl_basics.h"
#include "retroaa/types.h"
#include "shared_constants.h"

#include <cassert>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace retroaa {

const std::map<std::string, std::string>& embeddedFiles();  // generated from shaders/

namespace {

std::string withDefines(const std::string& source, const std::string& defines) {
  const size_t versionEnd = source.rfind("#version", 0) == 0 ? source.find('\n') : std::string::npos;
  if (versionEnd == std::string::npos) return defines + source;
  return source.substr(0, versionEnd + 1) + defines + "#line 2\n" + source.substr(versionEnd + 1);
}

bool isSampler(GLenum type) {
  switch (type) {
    case GL_SAMPLER_2D:
    case GL_INT_SAMPLER_2D:
    case GL_UNSIGNED_INT_SAMPLER_2D:
    case GL_SAMPLER_2D_MULTISAMPLE:
    case GL_INT_SAMPLER_2D_MULTISAMPLE:
    case GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE:
    case GL_SAMPLER_2D_ARRAY:
    case GL_SAMPLER_3D:
    case GL_SAMPLER_CUBE:
    case GL_SAMPLER_2D_SHADOW: return true;
    default: return false;
  }
}

// Every active sampler of `program` and the unit its binding names, array elements one by one.
std::vector<std::pair<std::string, int>> activeSamplerUnits(GLuint program) {
  std::vector<std::pair<std::string, int>> units;
  GLint count = 0;
  glGetProgramInterfaceiv(program, GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
  for (GLint index = 0; index < count; ++index) {
    const GLenum properties[] = {GL_TYPE, GL_ARRAY_SIZE, GL_LOCATION};
    GLint values[3] = {};
    glGetProgramResourceiv(program, GL_UNIFORM, GLuint(index), 3, properties, 3, nullptr, values);
    if (!isSampler(GLenum(values[0])) || values[2] < 0) continue;
    char name[128] = {};
    glGetProgramResourceName(program, GL_UNIFORM, GLuint(index), sizeof name, nullptr, name);
    std::string base = name;
    if (base.size() > 3 && base.compare(base.size() - 3, 3, "[0]") == 0) base.resize(base.size() - 3);
    for (GLint element = 0; element < values[1]; ++element) {
      GLint unit = -1;
      glGetUniformiv(program, values[2] + element, &unit);
      units.emplace_back(values[1] > 1 ? base + "[" + std::to_string(element) + "]" : base, unit);
    }
  }
  return units;
}

// The samplers bound outside any one program (shared_constants.h), with the unit the C++ side binds;
// -1: the array element's own index (G-buffer attachment i is on unit i).
constexpr std::pair<const char*, int> kSharedSamplerUnits[] = {{"uAttachments", -1},
                                                               {"uDepthBuffer", kUnitDepthStencil},
                                                               {"uSliceCountsOfDepth", kUnitSliceCounts},
                                                               {"uAssignment", kUnitSliceWeights}};

// Empty, or why the units of `samplers` cannot work: two samplers on one unit, or a shared one on a unit
// the C++ side does not bind it to.
std::string samplerUnitProblem(const std::vector<std::pair<std::string, int>>& samplers) {
  for (size_t i = 0; i < samplers.size(); ++i) {
    for (size_t j = 0; j < i; ++j)
      if (samplers[j].second == samplers[i].second)
        return "samplers '" + samplers[j].first + "' and '" + samplers[i].first + "' share texture unit " +
               std::to_string(samplers[i].second);
    const std::string& name = samplers[i].first;
    for (const auto& [shared, unit] : kSharedSamplerUnits) {
      const size_t length = std::strlen(shared);
      if (name.compare(0, length, shared) != 0 || (name.size() > length && name[length] != '[')) continue;
      const int expected = unit >= 0 ? unit : name.size() > length ? std::atoi(name.c_str() + length + 1) : 0;
      if (samplers[i].second != expected)
        return "sampler '" + name + "' is on texture unit " + std::to_string(samplers[i].second) +
               ", where the plugin binds unit " + std::to_string(expected);
    }
  }
  return "";
}

// Whether a line of `source` declares a uniform called `name` (whole identifier).
bool declaresUniform(const std::string& source, const std::string& name) {
  auto isIdentifier = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  std::istringstream lines(source);
  for (std::string line; std::getline(lines, line);) {
    if (line.find("uniform") == std::string::npos) continue;
    line = line.substr(0, line.find("//"));
    for (size_t at = line.find(name); at != std::string::npos; at = line.find(name, at + 1)) {
      const size_t end = at + name.size();
      if ((at == 0 || !isIdentifier(line[at - 1])) && (end == line.size() || !isIdentifier(line[end]))) return true;
    }
  }
  return false;
}

}  // namespace

GLint ShaderProgram::location(const char* name) const {
  for (const auto& [declared, location] : uniforms_)
    if (declared == name) return location;
  assert(!"a uniform set on a program that did not list it when built");
  return -1;
}

int ShaderProgram::unit(const char* sampler) const {
  for (const auto& [name, unit] : samplerUnits_)
    if (name == sampler) return unit;
  location(sampler);  // listed when built (or an assertion), and optimised away
  return -1;
}

void ShaderProgram::bindTexture(const char* sampler, GLuint texture) const {
  if (const int bound = unit(sampler); bound >= 0) glBindTextureUnit(GLuint(bound), texture);
}

void ShaderProgram::setDepthEncoding(const PluginContext& context) const {
  set("uDepthKnee", context.layout.depthEncoding.knee);
  set("uBackgroundAbove", context.layout.depthEncoding.backgroundAbove);
  const float* v = context.frame.viewMatrix;  // column-major: row 2 is v[2], v[6], v[10], v[14]
  const float viewDepthRow[4] = {v[2], v[6], v[10], v[14]};
  setVec4("uViewDepthRow", viewDepthRow);
  setDepthPlanes(context);
}

void ShaderProgram::setDepthPlanes(const PluginContext& context) const {
  set("uDepthNear", context.frame.nearPlane);
  set("uDepthFar", context.frame.farPlane);
}

ShaderLibrary::ShaderLibrary(ObjectCounter& counter, std::string overrideDirectory, Warn warn)
    : counter_(counter), overrideDirectory_(std::move(overrideDirectory)), warn_(std::move(warn)) {}

Result<std::string> ShaderLibrary::source(const std::string& path, bool allowOverride, bool& fromOverride,
                                          int depth) const {
  if (depth > 8) return Error{ErrorCode::ShaderError, "shader includes nest too deep at " + path};
  std::string text;
  const std::filesystem::path overridePath = std::filesystem::path(overrideDirectory_) / path;
  if (allowOverride && !overrideDirectory_.empty() && std::filesystem::is_regular_file(overridePath)) {
    std::ifstream in(overridePath);
    std::stringstream buffer;
    buffer << in.rdbuf();
    text = buffer.str();
    fromOverride = true;
  } else {
    const auto& files = embeddedFiles();
    const auto found = files.find(path);
    if (found == files.end()) return Error{ErrorCode::ShaderError, "no built-in shader " + path};
    text = found->second;
  }
  std::istringstream in(text);
  std::string line, out;
  while (std::getline(in, line)) {
    const std::string directive = "#include \"";
    if (line.rfind(directive, 0) == 0) {
      const size_t close = line.find('"', directive.size());
      const std::string included = line.substr(directive.size(), close - directive.size());
      Result<std::string> nested = source(included, allowOverride, fromOverride, depth + 1);
      if (!nested) return nested.error();
      out += nested.value();
    } else {
      out += line + "\n";
    }
  }
  return out;
}

Result<ShaderProgram> ShaderLibrary::link(const std::vector<Stage>& stages, const std::string& defines,
                                          const std::vector<std::string>& uniforms, bool allowOverride,
                                          bool& usedOverride) {
  const std::string& mainPath = stages.back().path;  // the stage the program is named after
  std::vector<GLuint> shaders;
  auto deleteShaders = [&shaders] {
    for (GLuint shader : shaders) glDeleteShader(shader);
  };
  std::string sources;  // every stage as compiled, for the uniform check
  for (const Stage& stage : stages) {
    Result<std::string> text = source(stage.path, allowOverride, usedOverride);
    std::string log;
    GLuint shader = 0;
    if (text) {
      const std::string compiled = withDefines(text.value(), sharedConstantDefines() + defines);
      shader = gl_basics::compileStage(stage.type, compiled, log);
      sources += compiled;
    }
    if (!shader) {
      deleteShaders();
      return Error{ErrorCode::ShaderError, text ? stage.path + " does not compile: " + log : text.error().message};
    }
    shaders.push_back(shader);
  }
  const GLuint program = glCreateProgram();
  for (GLuint shader : shaders) glAttachShader(program, shader);
  glLinkProgram(program);
  deleteShaders();
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    glGetProgramInfoLog(program, sizeof log, nullptr, log);
    glDeleteProgram(program);
    std::string names;
    for (const Stage& stage : stages) names += (names.empty() ? "" : " + ") + stage.path;
    return Error{ErrorCode::ShaderError, names + (stages.size() > 1 ? " do" : " does") + " not link: " + log};
  }
  const std::string label = "retroaa." + mainPath;
  glObjectLabel(GL_PROGRAM, program, -1, label.c_str());
  ShaderProgram built;
  built.program_ = GlProgram(counter_, program);
  for (const std::string& name : uniforms) {
    const GLint location = glGetUniformLocation(program, name.c_str());
    if (location < 0 && !declaresUniform(sources, name))
      return Error{ErrorCode::ShaderError, mainPath + " declares no uniform '" + name + "', which the plugin sets"};
    built.uniforms_.emplace_back(name, location);
  }
  built.samplerUnits_ = activeSamplerUnits(program);
  if (const std::string problem = samplerUnitProblem(built.samplerUnits_); !problem.empty())
    return Error{ErrorCode::ShaderError, mainPath + ": " + problem};
  return built;
}

Result<ShaderProgram> ShaderLibrary::build(const std::vector<Stage>& stages, const std::string& defines,
                                           std::initializer_list<const char*> uniforms) {
  const std::vector<std::string> names(uniforms.begin(), uniforms.end());
  bool usedOverride = false;
  Result<ShaderProgram> program = link(stages, defines, names, true, usedOverride);
  if (program || !usedOverride) return program;
  warn_("shader override in '" + overrideDirectory_ + "' failed, using the built-in " + stages.back().path +
        " instead: " + program.error().message);
  return link(stages, defines, names, false, usedOverride);
}

Result<ShaderProgram> ShaderLibrary::program(const std::string& vertexPath, const std::string& fragmentPath,
                                             const std::string& defines, std::initializer_list<const char*> uniforms) {
  return build({{GL_VERTEX_SHADER, vertexPath}, {GL_FRAGMENT_SHADER, fragmentPath}}, defines, uniforms);
}

Result<ShaderProgram> ShaderLibrary::computeProgram(const std::string& computePath, const std::string& defines,
                                                    std::initializer_list<const char*> uniforms) {
  return build({{GL_COMPUTE_SHADER, computePath}}, defines, uniforms);
}

}  // namespace retroaa
