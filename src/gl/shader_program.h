// A linked GLSL program built from embedded shader sources (shaders/*.glsl), with uniform setters.
// Internal to the render library; needs a current GL context.
#pragma once

#include <string>

#include <Eigen/Core>

namespace urdfsnap::gl {

class ShaderProgram {
 public:
  // Compiles shaders/<vertex_name> and shaders/<fragment_name> and links them. Throws
  // urdfsnap::Error with the shader's name and GL's info log when either step fails.
  ShaderProgram(const std::string& vertex_name, const std::string& fragment_name);
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  void Use() const;
  // Setters for the program in use; a uniform the linker removed is ignored.
  void Set(const char* name, const Eigen::Matrix4f& value) const;
  void Set(const char* name, const Eigen::Matrix3f& value) const;
  void Set(const char* name, const Eigen::Vector4f& value) const;
  void Set(const char* name, const Eigen::Vector3f& value) const;
  void Set(const char* name, int value) const;   // also a sampler's texture unit

 private:
  int Location(const char* name) const;
  unsigned id_ = 0;
};

}  // namespace urdfsnap::gl
