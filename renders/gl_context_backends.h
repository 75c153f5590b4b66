#pragma once
// The constructors of the back ends built into this library (private to renders/).

#include <memory>

#include "renders/gl_context.h"

namespace railjoint {

std::unique_ptr<GlContext> create_osmesa_context();  // osmesa_context.cpp
std::unique_ptr<GlContext> create_egl_context();     // egl_context.cpp

}  // namespace railjoint
