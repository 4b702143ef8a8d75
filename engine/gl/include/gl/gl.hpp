// The one include for OpenGL: the glad 4.5 core loader generated at configure time.
#pragma once

#include <glad/gl.h>
