// A linked GLSL program built from embedded shader sources (shaders/*.glsl), with uniform setters.
// Internal to the render library; needs a current GL context.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>

#include <Eigen/Core>

namespace urdfsnap::gl {

class ShaderProgram {
 public:
  // Compiles shaders/<vertex_name> and shaders/<fragment_name> and links them; each space-separated
  // word of `define` is #define'd in both (after their #version line), for the sources' #ifdef
  // variants.
  // Throws urdfsnap::Error with the shader's name and GL's info log when either step fails.
  ShaderProgram(const std::string& vertex_name, const std::string& fragment_name, const std::string& define = "");
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  void Use() const;
  // Setters for the program in use. A name that is not an active uniform of the program (a typo,
  // or one the linker removed as unused) throws urdfsnap::Error, as Drake's shader program does.
  void Set(const char* name, const Eigen::Matrix4f& value) const;
  void Set(const char* name, const Eigen::Matrix3f& value) const;
  void Set(const char* name, const Eigen::Vector4f& value) const;
  void Set(const char* name, const Eigen::Vector3f& value) const;
  void Set(const char* name, const Eigen::Vector2f& value) const;
  void Set(const char* name, float value) const;
  void Set(const char* name, int value) const;        // also a sampler's texture unit
  void Set(const char* name, unsigned value) const;

 private:
  int Location(const char* name) const;
  std::string name_;                    // "lit.vert + lit.frag" (with " TEXTURED"), for messages
  unsigned id_ = 0;
  std::map<std::string, int, std::less<>> locations_;   // the active uniforms, read after linking
};

// A ShaderProgram compiled and linked on first use, so that a renderer pays (in time, and in
// memory for the compiler's work) only for the programs its scenes need: a still of a robot never
// needs the text, label or point programs.
class LazyShaderProgram {
 public:
  LazyShaderProgram(std::string vertex_name, std::string fragment_name, std::string define = "")
      : vertex_name_(std::move(vertex_name)), fragment_name_(std::move(fragment_name)), define_(std::move(define)) {}

  // The program, made now if it was not yet (throws as ShaderProgram's constructor does).
  const ShaderProgram& Get() {
    if (!program_) program_.emplace(vertex_name_, fragment_name_, define_);
    return *program_;
  }

 private:
  std::string vertex_name_, fragment_name_, define_;
  std::optional<ShaderProgram> program_;
};

}  // namespace urdfsnap::gl
