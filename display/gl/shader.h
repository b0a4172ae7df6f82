#pragma once
// Compiling and linking GLSL programs. Failures are loud: they throw cavewall::Error naming the
// program, the stage and the driver's log, e.g.
//   "shader program 'scene': fragment stage failed to compile: 0:12(3): error: ..."

#include "display/gl/gl_object.h"

#include <string>
#include <string_view>

namespace cavewall::display::gl {

// Builds a program from vertex and fragment source (with their #version lines). Needs a
// current context; the program belongs to it (and to contexts sharing with it).
GlObject buildProgram(std::string_view name, std::string_view vertexSource, std::string_view fragmentSource);

// Builds a compute program from its source (with its #version line).
GlObject buildComputeProgram(std::string_view name, std::string_view computeSource);

// The location of a uniform; throws Error when the program has no active uniform of that name
// (a misspelt name is a bug that should not silently draw black).
GLint uniformLocation(GLuint program, std::string_view programName, const char* uniform);

}  // namespace cavewall::display::gl
