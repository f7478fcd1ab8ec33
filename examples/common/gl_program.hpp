// Compiling and linking the apps' own small GL programs (GLES2 calls, which
// desktop GL has too).
#pragma once

#include <GLES2/gl2.h>

#include <initializer_list>
#include <string>
#include <utility>

namespace example {

// Throws std::runtime_error with the GL info log when compiling or linking
// fails. `attributes` binds attribute names to locations before linking.
GLuint link_program(const char* vertex_source, const char* fragment_source,
                    std::initializer_list<std::pair<GLuint, const char*>> attributes);

// Throws std::runtime_error naming `where` when glGetError reports one.
void check_gl(const char* where);

}  // namespace example
