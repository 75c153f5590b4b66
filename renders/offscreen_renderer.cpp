// OffscreenRenderer on an OSMesa context (renders/gl_context.h, which gives
// the GL entry points too): the picture is drawn into a framebuffer object
// (multisampled and resolved into a single-sampled one for msaa) and read back.

#include "renders/offscreen_renderer.h"

#include <Eigen/LU>

#include <algorithm>
#include <cstring>
#include <initializer_list>
#include <stdexcept>
#include <string>

#include "renders/gl_context.h"

namespace railjoint {

bool rendering_available() { return true; }

namespace {

// Mesh shading: normals turned towards the viewer (so the winding of a mesh
// never makes it black), a key light, a head light and ambient, and a
// Blinn-Phong highlight. Lit per vertex: the fragment shader only passes the
// colour on, which is what llvmpipe's rasteriser spends its time on (the
// fill, not the vertices). For flat faces in an orthographic view it gives
// exactly the per-pixel result (one normal, one view direction); smooth rim
// normals interpolate across a rim facet a fraction of a degree wide.
constexpr const char* kMeshVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 colour;
uniform mat4 model;
uniform mat3 normal_matrix;  // inverse transpose of the model's linear part (the model may stretch)
uniform mat4 view_projection;
uniform bool orthographic;
uniform vec3 eye;
uniform vec3 to_viewer;
uniform vec3 to_light;
uniform float specular;
uniform float opacity;
out vec4 lit_colour;
void main() {
  vec4 world = model * vec4(position, 1.0);
  vec3 v = orthographic ? to_viewer : normalize(eye - world.xyz);
  vec3 n = normalize(normal_matrix * normal);
  if (dot(n, v) < 0.0) n = -n;
  float shade = 0.30 + 0.45 * max(dot(n, to_light), 0.0) + 0.25 * max(dot(n, v), 0.0);
  float highlight = specular * pow(max(dot(n, normalize(to_light + v)), 0.0), 24.0);
  lit_colour = vec4(colour * shade + vec3(highlight), opacity);
  gl_Position = view_projection * world;
}
)";

// Every program but the markers': the colour the vertex shader gave.
constexpr const char* kColourFragmentShader = R"(#version 330 core
in vec4 lit_colour;
out vec4 fragment;
void main() { fragment = lit_colour; }
)";

constexpr const char* kLineVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 colour;
uniform mat4 model;
uniform mat4 view_projection;
out vec4 lit_colour;
void main() {
  lit_colour = vec4(colour, 1.0);
  gl_Position = view_projection * model * vec4(position, 1.0);
}
)";

// Round markers with a dark rim, so they read on any background; rings leave
// what they mark visible through the middle.
constexpr const char* kMarkerVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 colour;
layout(location = 2) in float diameter;
layout(location = 3) in float ring;
uniform mat4 view_projection;
out vec3 marker_colour;
out float marker_ring;
void main() {
  marker_colour = colour;
  marker_ring = ring;
  gl_PointSize = diameter;
  gl_Position = view_projection * vec4(position, 1.0);
}
)";

constexpr const char* kMarkerFragmentShader = R"(#version 330 core
in vec3 marker_colour;
in float marker_ring;
out vec4 fragment;
void main() {
  float r = length(gl_PointCoord - vec2(0.5)) * 2.0;
  if (r > 1.0) discard;
  if (marker_ring > 0.5 && r < 0.55) discard;
  fragment = vec4(r > 0.85 || (marker_ring > 0.5 ? r < 0.65 : r > 0.7) ? marker_colour * 0.35 : marker_colour, 1.0);
}
)";

// The labels, in pixels (origin top-left, y down). The division by the
// viewport is kept as it is: a pixel-to-clip matrix rounds differently and
// moved a label's edge by one pixel on an exact tie.
constexpr const char* kOverlayVertexShader = R"(#version 330 core
layout(location = 0) in vec2 position_px;
layout(location = 1) in vec3 colour;
uniform vec2 viewport_px;
out vec4 lit_colour;
void main() {
  lit_colour = vec4(colour, 1.0);
  gl_Position = vec4(position_px.x / viewport_px.x * 2.0 - 1.0, 1.0 - position_px.y / viewport_px.y * 2.0, 0.0, 1.0);
}
)";

// A shader's compile or a program's link status: on failure the object is
// deleted and the error names it with GL's log. Shaders and programs have
// functions of the same types for this.
void check_built(GLuint object, GLenum status, PFNGLGETSHADERIVPROC get_status, PFNGLGETSHADERINFOLOGPROC get_log,
                 PFNGLDELETESHADERPROC destroy, const std::string& failure) {
  GLint ok = GL_FALSE;
  get_status(object, status, &ok);
  if (ok == GL_TRUE) return;
  char log[2048] = {};
  get_log(object, sizeof(log) - 1, nullptr, log);
  destroy(object);
  throw std::runtime_error("renderer: " + failure + log);
}

GLuint compile(const GlFunctions& gl, GLenum type, const char* source, const char* name) {
  const GLuint shader = gl.CreateShader(type);
  gl.ShaderSource(shader, 1, &source, nullptr);
  gl.CompileShader(shader);
  check_built(shader, GL_COMPILE_STATUS, gl.GetShaderiv, gl.GetShaderInfoLog, gl.DeleteShader,
              std::string("shader '") + name + "' did not compile: ");
  return shader;
}

GLuint link_program(const GlFunctions& gl, const char* vertex, const char* fragment, const char* name) {
  const GLuint vs = compile(gl, GL_VERTEX_SHADER, vertex, name);
  const GLuint fs = compile(gl, GL_FRAGMENT_SHADER, fragment, name);
  const GLuint program = gl.CreateProgram();
  gl.AttachShader(program, vs);
  gl.AttachShader(program, fs);
  gl.LinkProgram(program);
  gl.DeleteShader(vs);
  gl.DeleteShader(fs);
  check_built(program, GL_LINK_STATUS, gl.GetProgramiv, gl.GetProgramInfoLog, gl.DeleteProgram,
              std::string("program '") + name + "' did not link: ");
  return program;
}

struct VertexBuffer {
  GLuint vao = 0;
  GLuint vbo = 0;
  GLsizei count = 0;
};

// Interleaved float attributes with the given component counts.
VertexBuffer make_buffer(const GlFunctions& gl, std::initializer_list<int> components) {
  VertexBuffer buffer;
  gl.GenVertexArrays(1, &buffer.vao);
  gl.GenBuffers(1, &buffer.vbo);
  gl.BindVertexArray(buffer.vao);
  gl.BindBuffer(GL_ARRAY_BUFFER, buffer.vbo);
  int stride = 0;
  for (int c : components) stride += c;
  int offset = 0;
  GLuint location = 0;
  for (int c : components) {
    gl.EnableVertexAttribArray(location);
    gl.VertexAttribPointer(location, c, GL_FLOAT, GL_FALSE, static_cast<GLsizei>(stride * sizeof(float)),
                           reinterpret_cast<const void*>(static_cast<std::size_t>(offset) * sizeof(float)));
    offset += c;
    ++location;
  }
  gl.BindVertexArray(0);
  return buffer;
}

void upload(const GlFunctions& gl, VertexBuffer& buffer, const std::vector<float>& data, GLsizei count,
            GLenum usage) {
  gl.BindBuffer(GL_ARRAY_BUFFER, buffer.vbo);
  gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(), usage);
  buffer.count = count;
}

void append(std::vector<float>& out, const Eigen::Vector3f& v) { out.insert(out.end(), {v.x(), v.y(), v.z()}); }

// A framebuffer object with a colour and, unless it only receives the
// multisampled picture's resolve, a depth renderbuffer.
GLuint make_framebuffer(const GlFunctions& gl, int width, int height, int samples, bool with_depth) {
  GLuint fbo = 0;
  gl.GenFramebuffers(1, &fbo);
  gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
  auto attach = [&](GLenum format, GLenum attachment) {
    GLuint buffer = 0;
    gl.GenRenderbuffers(1, &buffer);
    gl.BindRenderbuffer(GL_RENDERBUFFER, buffer);
    gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, attachment, GL_RENDERBUFFER, buffer);
  };
  attach(GL_RGBA8, GL_COLOR_ATTACHMENT0);
  if (with_depth) attach(GL_DEPTH_COMPONENT24, GL_DEPTH_ATTACHMENT);
  const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error("renderer: a " + std::to_string(width) + "x" + std::to_string(height) + " framebuffer with " +
                             std::to_string(samples) + " samples is incomplete (status " + std::to_string(status) + ")");
  }
  return fbo;
}

std::vector<float> interleave(const std::vector<MeshVertex>& vertices) {
  std::vector<float> data;
  data.reserve(vertices.size() * 9);
  for (const auto& v : vertices) {
    append(data, v.position_m);
    append(data, v.normal);
    append(data, v.colour);
  }
  return data;
}

}  // namespace

struct OffscreenRenderer::Impl {
  std::unique_ptr<GlContext> context;
  GlFunctions gl;
  int width_px = 0;
  int height_px = 0;
  bool msaa = false;
  bool fxaa = false;
  std::string version;
  std::string renderer;

  GLuint draw_target = 0;     // msaa: the multisampled scenes
  GLuint resolve_target = 0;  // single-sampled, what is read back; the scenes' target unless msaa
  GLuint mesh_program = 0;
  GLuint line_program = 0;
  GLuint marker_program = 0;
  GLuint overlay_program = 0;
  std::vector<VertexBuffer> buffers;  // by MeshHandle: triangle lists and line strips
  VertexBuffer markers;
  VertexBuffer overlay;

  VertexBuffer& buffer(MeshHandle mesh) {
    if (mesh < 0 || static_cast<std::size_t>(mesh) >= buffers.size()) {
      throw std::out_of_range("renderer: unknown mesh handle " + std::to_string(mesh));
    }
    return buffers[static_cast<std::size_t>(mesh)];
  }
  MeshHandle add(VertexBuffer buffer) {
    buffers.push_back(buffer);
    return static_cast<MeshHandle>(buffers.size() - 1);
  }
  void draw_scene(const SceneDraw& scene);
  void draw_overlay(const std::vector<OverlayVertex>& overlay);
};

OffscreenRenderer::OffscreenRenderer(int width_px, int height_px, Antialiasing antialiasing)
    : impl_(std::make_unique<Impl>()) {
  if (width_px <= 0 || height_px <= 0) {
    throw std::invalid_argument("renderer: image size must be positive, got " + std::to_string(width_px) + "x" +
                                std::to_string(height_px));
  }
  Impl& s = *impl_;
  s.width_px = width_px;
  s.height_px = height_px;
  s.msaa = antialiasing == Antialiasing::msaa;
  s.fxaa = antialiasing == Antialiasing::fxaa;
  // Destroying the context frees every GL object made in it: on an
  // exception below, and with the renderer.
  s.context = std::make_unique<GlContext>();
  CurrentContext current(*s.context);
  s.gl = s.context->load_functions();
  const GlFunctions& gl = s.gl;
  const auto* version = reinterpret_cast<const char*>(gl.GetString(GL_VERSION));
  const auto* renderer = reinterpret_cast<const char*>(gl.GetString(GL_RENDERER));
  s.version = version != nullptr ? version : "unknown";
  s.renderer = renderer != nullptr ? renderer : "unknown";

  s.resolve_target = make_framebuffer(gl, width_px, height_px, 0, !s.msaa);
  if (s.msaa) {
    GLint max_samples = 1;
    gl.GetIntegerv(GL_MAX_SAMPLES, &max_samples);
    s.draw_target = make_framebuffer(gl, width_px, height_px, std::clamp(max_samples, 1, 4), true);
  }
  s.mesh_program = link_program(gl, kMeshVertexShader, kColourFragmentShader, "mesh");
  s.line_program = link_program(gl, kLineVertexShader, kColourFragmentShader, "line");
  s.marker_program = link_program(gl, kMarkerVertexShader, kMarkerFragmentShader, "marker");
  s.overlay_program = link_program(gl, kOverlayVertexShader, kColourFragmentShader, "overlay");
  s.markers = make_buffer(gl, {3, 3, 1, 1});
  s.overlay = make_buffer(gl, {2, 3});
}

OffscreenRenderer::~OffscreenRenderer() = default;

const std::string& OffscreenRenderer::gl_version() const { return impl_->version; }
const std::string& OffscreenRenderer::gl_renderer() const { return impl_->renderer; }

MeshHandle OffscreenRenderer::add_triangles(const std::vector<MeshVertex>& vertices) {
  CurrentContext current(*impl_->context);
  VertexBuffer buffer = make_buffer(impl_->gl, {3, 3, 3});
  upload(impl_->gl, buffer, interleave(vertices), static_cast<GLsizei>(vertices.size()), GL_STATIC_DRAW);
  return impl_->add(buffer);
}

void OffscreenRenderer::update_triangles(MeshHandle mesh, const std::vector<MeshVertex>& vertices) {
  VertexBuffer& buffer = impl_->buffer(mesh);
  CurrentContext current(*impl_->context);
  upload(impl_->gl, buffer, interleave(vertices), static_cast<GLsizei>(vertices.size()), GL_DYNAMIC_DRAW);
}

MeshHandle OffscreenRenderer::add_line_strip(const std::vector<LineVertex>& vertices) {
  CurrentContext current(*impl_->context);
  std::vector<float> data;
  data.reserve(vertices.size() * 6);
  for (const auto& v : vertices) {
    append(data, v.position_m);
    append(data, v.colour);
  }
  VertexBuffer buffer = make_buffer(impl_->gl, {3, 3});
  upload(impl_->gl, buffer, data, static_cast<GLsizei>(vertices.size()), GL_STATIC_DRAW);
  return impl_->add(buffer);
}

void OffscreenRenderer::Impl::draw_scene(const SceneDraw& scene) {
  const PixelRect rect = scene.viewport.value_or(PixelRect{0, 0, width_px, height_px});
  // GL's window origin is the bottom-left corner.
  const GLint gl_y = height_px - rect.y - rect.height;
  gl.Viewport(rect.x, gl_y, rect.width, rect.height);
  gl.Enable(GL_SCISSOR_TEST);
  gl.Scissor(rect.x, gl_y, rect.width, rect.height);
  gl.ClearColor(scene.background.x(), scene.background.y(), scene.background.z(), 1.0f);
  gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  const Eigen::Matrix4f view_projection = scene.projection * scene.view;

  // translucent: which draws of the list to take (opaque ones, or the others).
  auto draw_list = [&](GLuint program, const std::vector<MeshDraw>& draws, GLenum mode, bool translucent) {
    gl.UseProgram(program);
    gl.UniformMatrix4fv(gl.GetUniformLocation(program, "view_projection"), 1, GL_FALSE, view_projection.data());
    const GLint model_location = gl.GetUniformLocation(program, "model");
    const GLint normal_location = gl.GetUniformLocation(program, "normal_matrix");  // -1 for lines: ignored
    const GLint specular_location = gl.GetUniformLocation(program, "specular");
    const GLint opacity_location = gl.GetUniformLocation(program, "opacity");
    for (const auto& d : draws) {
      if ((d.opacity < 1.0f) != translucent) continue;
      const VertexBuffer& b = buffer(d.mesh);
      const GLsizei count = d.vertex_count < 0 ? b.count : std::min<GLsizei>(d.vertex_count, b.count);
      if (count <= 0) continue;
      gl.UniformMatrix4fv(model_location, 1, GL_FALSE, d.model.data());
      if (normal_location >= 0) {
        // Normals of a stretched surface transform with the inverse transpose.
        const Eigen::Matrix3f normal_matrix = d.model.topLeftCorner<3, 3>().inverse().transpose();
        gl.UniformMatrix3fv(normal_location, 1, GL_FALSE, normal_matrix.data());
      }
      if (specular_location >= 0) gl.Uniform1f(specular_location, d.specular);
      if (opacity_location >= 0) gl.Uniform1f(opacity_location, d.opacity);
      if (d.cull_back_faces) gl.Enable(GL_CULL_FACE);
      gl.BindVertexArray(b.vao);
      gl.DrawArrays(mode, 0, count);
      if (d.cull_back_faces) gl.Disable(GL_CULL_FACE);
    }
  };

  gl.UseProgram(mesh_program);
  gl.Uniform1i(gl.GetUniformLocation(mesh_program, "orthographic"), scene.orthographic ? 1 : 0);
  gl.Uniform3fv(gl.GetUniformLocation(mesh_program, "eye"), 1, scene.eye_m.data());
  gl.Uniform3fv(gl.GetUniformLocation(mesh_program, "to_viewer"), 1, scene.to_viewer.data());
  gl.Uniform3fv(gl.GetUniformLocation(mesh_program, "to_light"), 1, scene.to_light.data());
  draw_list(mesh_program, scene.meshes, GL_TRIANGLES, false);
  draw_list(line_program, scene.line_strips, GL_LINE_STRIP, false);
  // Translucent meshes over everything opaque: blended, depth tested, not written.
  gl.Enable(GL_BLEND);
  gl.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  gl.DepthMask(GL_FALSE);
  draw_list(mesh_program, scene.meshes, GL_TRIANGLES, true);
  gl.DepthMask(GL_TRUE);
  gl.Disable(GL_BLEND);

  gl.Disable(GL_DEPTH_TEST);
  if (!scene.markers.empty()) {
    std::vector<float> data;
    data.reserve(scene.markers.size() * 8);
    for (const auto& m : scene.markers) {
      append(data, m.position_m);
      append(data, m.colour);
      data.push_back(m.diameter_px);
      data.push_back(m.ring ? 1.0f : 0.0f);
    }
    upload(gl, markers, data, static_cast<GLsizei>(scene.markers.size()), GL_STREAM_DRAW);
    gl.UseProgram(marker_program);
    gl.UniformMatrix4fv(gl.GetUniformLocation(marker_program, "view_projection"), 1, GL_FALSE,
                        view_projection.data());
    gl.BindVertexArray(markers.vao);
    gl.DrawArrays(GL_POINTS, 0, markers.count);
  }
  gl.Disable(GL_SCISSOR_TEST);
}

// The labels on a transparent ground.
void OffscreenRenderer::Impl::draw_overlay(const std::vector<OverlayVertex>& vertices) {
  gl.Disable(GL_DEPTH_TEST);
  gl.ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  gl.Clear(GL_COLOR_BUFFER_BIT);
  std::vector<float> data;
  data.reserve(vertices.size() * 5);
  for (const auto& v : vertices) {
    data.insert(data.end(), {v.position_px.x(), v.position_px.y()});
    append(data, v.colour);
  }
  upload(gl, overlay, data, static_cast<GLsizei>(vertices.size()), GL_STREAM_DRAW);
  gl.UseProgram(overlay_program);
  gl.Uniform2f(gl.GetUniformLocation(overlay_program, "viewport_px"), static_cast<float>(width_px),
               static_cast<float>(height_px));
  gl.BindVertexArray(overlay.vao);
  gl.DrawArrays(GL_TRIANGLES, 0, overlay.count);
}

void OffscreenRenderer::draw(const FrameDrawList& frame, ReadBackFrame& out) {
  Impl& s = *impl_;
  CurrentContext current(*s.context);
  const GlFunctions& gl = s.gl;
  gl.BindFramebuffer(GL_FRAMEBUFFER, s.msaa ? s.draw_target : s.resolve_target);
  gl.Enable(GL_PROGRAM_POINT_SIZE);
  if (s.msaa) gl.Enable(GL_MULTISAMPLE);

  // A frame that stopped half-way (an exception in draw_scene) may have left
  // the scissor test on or depth writes off: a clear would then miss pixels.
  gl.Disable(GL_SCISSOR_TEST);
  gl.DepthMask(GL_TRUE);
  // The background; each scene clears its own rectangle.
  gl.Viewport(0, 0, s.width_px, s.height_px);
  gl.ClearColor(frame.background.x(), frame.background.y(), frame.background.z(), 1.0f);
  gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  for (const SceneDraw& scene : frame.scenes) s.draw_scene(scene);
  gl.Viewport(0, 0, s.width_px, s.height_px);
  if (s.msaa) {  // resolve: each pixel the mean of its samples
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, s.draw_target);
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, s.resolve_target);
    gl.BlitFramebuffer(0, 0, s.width_px, s.height_px, 0, 0, s.width_px, s.height_px, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  gl.BindFramebuffer(GL_FRAMEBUFFER, s.resolve_target);
  // RGBA is Mesa's fast read path (a copy); RGB would convert pixel by pixel.
  const std::size_t pixels = static_cast<std::size_t>(s.width_px) * static_cast<std::size_t>(s.height_px);
  out.width_px = s.width_px;
  out.height_px = s.height_px;
  out.fxaa = s.fxaa;
  out.picture_rgba.resize(pixels * 4);
  gl.ReadPixels(0, 0, s.width_px, s.height_px, GL_RGBA, GL_UNSIGNED_BYTE, out.picture_rgba.data());
  // The labels apart, so that finish_frame lays them over the picture after FXAA, crisp.
  out.labels_rgba.clear();
  if (!frame.overlay.empty()) {
    s.draw_overlay(frame.overlay);
    out.labels_rgba.resize(pixels * 4);
    gl.ReadPixels(0, 0, s.width_px, s.height_px, GL_RGBA, GL_UNSIGNED_BYTE, out.labels_rgba.data());
  }
  gl.BindVertexArray(0);
  const GLenum error = gl.GetError();
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  if (error != GL_NO_ERROR) throw std::runtime_error("renderer: GL error " + std::to_string(error) + " in a frame");
}

void OffscreenRenderer::draw(const FrameDrawList& frame, RgbImage& out) {
  ReadBackFrame read_back;
  draw(frame, read_back);
  finish_frame(read_back, out);
}

}  // namespace railjoint
