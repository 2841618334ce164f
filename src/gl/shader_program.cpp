// GLSL compilation and linking with readable errors (after Drake's internal_shader_program.cc).
#include "gl/internal/shader_program.h"

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "common/error.h"
#include "gl/internal/embedded_shaders.h"
#include "gl/internal/gl_api.h"

namespace urdfsnap::gl {

namespace {

std::string InfoLog(GLuint object, bool is_program) {
  GLint length = 0;
  if (is_program) {
    glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  } else {
    glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  }
  std::vector<char> log(static_cast<size_t>(length) + 1, '\0');
  if (is_program) {
    glGetProgramInfoLog(object, length, nullptr, log.data());
  } else {
    glGetShaderInfoLog(object, length, nullptr, log.data());
  }
  return log.data();
}

// Compiles shaders/<name>, with each space-separated word of `defines` #define'd at the end of its
// #version line (GLSL wants #version before anything but comments).
GLuint Compile(GLenum stage, const std::string& name, const std::string& defines) {
  const std::string_view source = EmbeddedShader(name);
  const size_t version_end = std::min(source.find('\n', source.find("#version")), source.size());
  std::string defined;
  std::istringstream words(defines);
  for (std::string word; words >> word;) defined += "\n#define " + word;
  const GLchar* texts[3] = {source.data(), defined.data(), source.data() + version_end};
  const GLint lengths[3] = {static_cast<GLint>(version_end), static_cast<GLint>(defined.size()),
                            static_cast<GLint>(source.size() - version_end)};
  const GLuint shader = glCreateShader(stage);
  glShaderSource(shader, 3, texts, lengths);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = InfoLog(shader, false);
    glDeleteShader(shader);
    throw Error("shader '" + name + "' failed to compile: " + log);
  }
  return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const std::string& vertex_name, const std::string& fragment_name,
                             const std::string& define)
    : name_(vertex_name + " + " + fragment_name + (define.empty() ? "" : " " + define)) {
  const GLuint vertex = Compile(GL_VERTEX_SHADER, vertex_name, define);
  const GLuint fragment = Compile(GL_FRAGMENT_SHADER, fragment_name, define);
  id_ = glCreateProgram();
  glAttachShader(id_, vertex);
  glAttachShader(id_, fragment);
  glLinkProgram(id_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = InfoLog(id_, true);
    glDeleteProgram(id_);
    throw Error("shader program '" + name_ + "' failed to link: " + log);
  }
  GLint count = 0;
  glGetProgramiv(id_, GL_ACTIVE_UNIFORMS, &count);
  for (GLint i = 0; i < count; ++i) {
    GLchar name[256];
    GLsizei length = 0;
    GLint size = 0;
    GLenum type = 0;
    glGetActiveUniform(id_, static_cast<GLuint>(i), sizeof name, &length, &size, &type, name);
    locations_.emplace(std::string(name, static_cast<size_t>(length)), glGetUniformLocation(id_, name));
  }
}

ShaderProgram::~ShaderProgram() { glDeleteProgram(id_); }

void ShaderProgram::Use() const { glUseProgram(id_); }

int ShaderProgram::Location(const char* name) const {
  const auto it = locations_.find(std::string_view(name));
  if (it == locations_.end()) {
    throw Error("shader program " + name_ + " has no active uniform '" + name + "'");
  }
  return it->second;
}

void ShaderProgram::Set(const char* name, const Eigen::Matrix4f& value) const {
  glUniformMatrix4fv(Location(name), 1, GL_FALSE, value.data());
}

void ShaderProgram::Set(const char* name, const Eigen::Matrix3f& value) const {
  glUniformMatrix3fv(Location(name), 1, GL_FALSE, value.data());
}

void ShaderProgram::Set(const char* name, const Eigen::Vector4f& value) const {
  glUniform4fv(Location(name), 1, value.data());
}

void ShaderProgram::Set(const char* name, const Eigen::Vector3f& value) const {
  glUniform3fv(Location(name), 1, value.data());
}

void ShaderProgram::Set(const char* name, const Eigen::Vector2f& value) const {
  glUniform2fv(Location(name), 1, value.data());
}

void ShaderProgram::Set(const char* name, float value) const { glUniform1f(Location(name), value); }

void ShaderProgram::Set(const char* name, int value) const { glUniform1i(Location(name), value); }

void ShaderProgram::Set(const char* name, unsigned value) const { glUniform1ui(Location(name), value); }

}  // namespace urdfsnap::gl
