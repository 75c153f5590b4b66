#pragma once
// Which library gives the renderer its OpenGL context. Both are Mesa's
// software rasteriser (llvmpipe) here and draw the same pixels:
//   osmesa  OSMesa, the default while Debian ships it (Mesa 25.1 removed it);
//   egl     EGL on the surfaceless platform (EGL_MESA_platform_surfaceless),
//           its successor; no window system, no device node needed.
// The renderer draws into its own framebuffer objects either way, so the
// back end only makes a context current and hands out GL entry points.
// No GL type appears here.

#include <optional>
#include <string>

namespace railjoint {

enum class GlBackend { osmesa, egl };

const char* to_string(GlBackend backend);

/// Whether this build can create a context of that kind (CMake options
/// RAILJOINT_WITH_OSMESA / RAILJOINT_WITH_EGL and the packages found).
bool gl_backend_built(GlBackend backend);

/// The back end named by the environment variable RAILJOINT_GL ("osmesa" or
/// "egl", case-sensitive); unset or empty: OSMesa when built, else EGL. Throws
/// std::invalid_argument for any other value and std::runtime_error when the
/// named back end is not in this build, or when neither is.
GlBackend gl_backend_from_environment();

/// Whether RAILJOINT_GL names the back end (set and not empty); otherwise
/// gl_backend_from_environment takes the default.
bool gl_backend_named_in_environment();

/// Parses "osmesa" / "egl"; nullopt otherwise.
std::optional<GlBackend> parse_gl_backend(const std::string& name);

}  // namespace railjoint
