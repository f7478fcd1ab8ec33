#include "common/gl_program.hpp"

#include <stdexcept>
#include <vector>

namespace example {

namespace {

std::string info_log(GLuint object, bool program) {
  GLint length = 0;
  if (program)
    glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  else
    glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  if (program)
    glGetProgramInfoLog(object, length, nullptr, log.data());
  else
    glGetShaderInfoLog(object, length, nullptr, log.data());
  return log.data();
}

GLuint compile(GLenum type, const char* source) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    const std::string log = info_log(shader, false);
    glDeleteShader(shader);
    throw std::runtime_error("shader does not compile: " + log);
  }
  return shader;
}

}  // namespace

GLuint link_program(const char* vertex_source, const char* fragment_source,
                    std::initializer_list<std::pair<GLuint, const char*>> attributes) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex_source);
  const GLuint fs = compile(GL_FRAGMENT_SHADER, fragment_source);
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  for (const auto& [location, name] : attributes) glBindAttribLocation(program, location, name);
  glLinkProgram(program);
  glDeleteShader(vs);  // flagged; freed with the program
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string log = info_log(program, true);
    glDeleteProgram(program);
    throw std::runtime_error("program does not link: " + log);
  }
  return program;
}

void check_gl(const char* where) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) throw std::runtime_error(std::string("GL error ") + std::to_string(error) + " " + where);
}

}  // namespace example
