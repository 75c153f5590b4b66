// OSMesa implementation of OffscreenRenderer (built when RAILJOINT_WITH_OSMESA
// is on and pkg-config finds osmesa). libOSMesa exports the GL entry points
// itself, so the core-profile functions are called directly.

#include "renders/offscreen_renderer.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/glext.h>

#include <Eigen/LU>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace railjoint {

bool rendering_available() { return true; }

namespace {

// Mesh shading: flat face normals turned towards the viewer (so the winding of
// a mesh never makes it black), a key light, a head light and ambient.
constexpr const char* kMeshVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 colour;
uniform mat4 model;
uniform mat3 normal_matrix;  // inverse transpose of the model's linear part (the model may stretch)
uniform mat4 view_projection;
out vec3 world_position;
out vec3 world_normal;
out vec3 base_colour;
void main() {
  vec4 world = model * vec4(position, 1.0);
  world_position = world.xyz;
  world_normal = normal_matrix * normal;
  base_colour = colour;
  gl_Position = view_projection * world;
}
)";

constexpr const char* kMeshFragmentShader = R"(#version 330 core
in vec3 world_position;
in vec3 world_normal;
in vec3 base_colour;
uniform bool orthographic;
uniform vec3 eye;
uniform vec3 to_viewer;
uniform vec3 to_light;
out vec4 fragment;
void main() {
  vec3 v = orthographic ? to_viewer : normalize(eye - world_position);
  vec3 n = normalize(world_normal);
  if (dot(n, v) < 0.0) n = -n;
  float shade = 0.30 + 0.45 * max(dot(n, to_light), 0.0) + 0.25 * max(dot(n, v), 0.0);
  fragment = vec4(base_colour * shade, 1.0);
}
)";

constexpr const char* kLineVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 colour;
uniform mat4 model;
uniform mat4 view_projection;
out vec3 line_colour;
void main() {
  line_colour = colour;
  gl_Position = view_projection * model * vec4(position, 1.0);
}
)";

constexpr const char* kLineFragmentShader = R"(#version 330 core
in vec3 line_colour;
out vec4 fragment;
void main() { fragment = vec4(line_colour, 1.0); }
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

constexpr const char* kOverlayVertexShader = R"(#version 330 core
layout(location = 0) in vec2 position_px;
layout(location = 1) in vec3 colour;
uniform vec2 viewport_px;
out vec3 overlay_colour;
void main() {
  overlay_colour = colour;
  gl_Position = vec4(position_px.x / viewport_px.x * 2.0 - 1.0, 1.0 - position_px.y / viewport_px.y * 2.0, 0.0, 1.0);
}
)";

constexpr const char* kOverlayFragmentShader = R"(#version 330 core
in vec3 overlay_colour;
out vec4 fragment;
void main() { fragment = vec4(overlay_colour, 1.0); }
)";

GLuint compile(GLenum type, const char* source, const char* name) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[2048] = {};
    glGetShaderInfoLog(shader, sizeof(log) - 1, nullptr, log);
    glDeleteShader(shader);
    throw std::runtime_error(std::string("renderer: shader '") + name + "' did not compile: " + log);
  }
  return shader;
}

GLuint link_program(const char* vertex, const char* fragment, const char* name) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex, name);
  const GLuint fs = compile(GL_FRAGMENT_SHADER, fragment, name);
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[2048] = {};
    glGetProgramInfoLog(program, sizeof(log) - 1, nullptr, log);
    glDeleteProgram(program);
    throw std::runtime_error(std::string("renderer: program '") + name + "' did not link: " + log);
  }
  return program;
}

struct VertexBuffer {
  GLuint vao = 0;
  GLuint vbo = 0;
  GLsizei count = 0;
};

// Interleaved float attributes with the given component counts.
VertexBuffer make_buffer(std::initializer_list<int> components) {
  VertexBuffer buffer;
  glGenVertexArrays(1, &buffer.vao);
  glGenBuffers(1, &buffer.vbo);
  glBindVertexArray(buffer.vao);
  glBindBuffer(GL_ARRAY_BUFFER, buffer.vbo);
  int stride = 0;
  for (int c : components) stride += c;
  int offset = 0;
  GLuint location = 0;
  for (int c : components) {
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, c, GL_FLOAT, GL_FALSE, static_cast<GLsizei>(stride * sizeof(float)),
                          reinterpret_cast<const void*>(static_cast<std::size_t>(offset) * sizeof(float)));
    offset += c;
    ++location;
  }
  glBindVertexArray(0);
  return buffer;
}

void upload(VertexBuffer& buffer, const std::vector<float>& data, GLsizei count, GLenum usage) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer.vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(), usage);
  buffer.count = count;
}

void append(std::vector<float>& out, const Eigen::Vector3f& v) { out.insert(out.end(), {v.x(), v.y(), v.z()}); }

}  // namespace

struct OffscreenRenderer::Impl {
  OSMesaContext context = nullptr;
  int width_px = 0;
  int height_px = 0;
  std::vector<unsigned char> rgba;  // OSMesa's colour buffer, rows bottom first
  std::string version;
  std::string renderer;

  GLuint mesh_program = 0;
  GLuint line_program = 0;
  GLuint marker_program = 0;
  GLuint overlay_program = 0;
  std::vector<VertexBuffer> meshes;
  std::vector<VertexBuffer> lines;
  VertexBuffer markers;
  VertexBuffer overlay;

  void make_current() {
    if (OSMesaMakeCurrent(context, rgba.data(), GL_UNSIGNED_BYTE, width_px, height_px) != GL_TRUE) {
      throw std::runtime_error("renderer: OSMesaMakeCurrent failed for a " + std::to_string(width_px) + "x" +
                               std::to_string(height_px) + " buffer");
    }
  }

  void release() {
    if (context == nullptr) return;
    if (OSMesaMakeCurrent(context, rgba.data(), GL_UNSIGNED_BYTE, width_px, height_px) == GL_TRUE) {
      auto free_buffer = [](VertexBuffer& b) {
        if (b.vbo != 0) glDeleteBuffers(1, &b.vbo);
        if (b.vao != 0) glDeleteVertexArrays(1, &b.vao);
      };
      for (auto& b : meshes) free_buffer(b);
      for (auto& b : lines) free_buffer(b);
      free_buffer(markers);
      free_buffer(overlay);
      for (GLuint p : {mesh_program, line_program, marker_program, overlay_program}) {
        if (p != 0) glDeleteProgram(p);
      }
    }
    OSMesaDestroyContext(context);
    context = nullptr;
  }
};

OffscreenRenderer::OffscreenRenderer(int width_px, int height_px) : impl_(std::make_unique<Impl>()) {
  if (width_px <= 0 || height_px <= 0) {
    throw std::invalid_argument("renderer: image size must be positive, got " + std::to_string(width_px) + "x" +
                                std::to_string(height_px));
  }
  Impl& s = *impl_;
  s.width_px = width_px;
  s.height_px = height_px;
  s.rgba.assign(static_cast<std::size_t>(width_px) * static_cast<std::size_t>(height_px) * 4, 0);

  // OSMesaCreateContextAttribs gives no depth buffer unless asked for one.
  const int attributes[] = {OSMESA_FORMAT,       OSMESA_RGBA,         OSMESA_DEPTH_BITS,
                            24,                  OSMESA_STENCIL_BITS, 0,
                            OSMESA_ACCUM_BITS,   0,                   OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                            OSMESA_CONTEXT_MINOR_VERSION, 3,          0};
  s.context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (s.context == nullptr) {
    throw std::runtime_error("renderer: OSMesa could not create a core-profile GL 3.3 context with a 24-bit depth buffer");
  }
  try {
    s.make_current();
    GLint depth_w = 0, depth_h = 0, depth_bytes = 0;
    void* depth = nullptr;
    if (OSMesaGetDepthBuffer(s.context, &depth_w, &depth_h, &depth_bytes, &depth) != GL_TRUE || depth == nullptr) {
      throw std::runtime_error("renderer: the OSMesa context has no depth buffer");
    }
    const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    s.version = version != nullptr ? version : "unknown";
    s.renderer = renderer != nullptr ? renderer : "unknown";

    s.mesh_program = link_program(kMeshVertexShader, kMeshFragmentShader, "mesh");
    s.line_program = link_program(kLineVertexShader, kLineFragmentShader, "line");
    s.marker_program = link_program(kMarkerVertexShader, kMarkerFragmentShader, "marker");
    s.overlay_program = link_program(kOverlayVertexShader, kOverlayFragmentShader, "overlay");
    s.markers = make_buffer({3, 3, 1, 1});
    s.overlay = make_buffer({2, 3});
    glViewport(0, 0, width_px, height_px);
    glEnable(GL_PROGRAM_POINT_SIZE);
  } catch (...) {
    s.release();
    throw;
  }
}

OffscreenRenderer::~OffscreenRenderer() {
  if (impl_) impl_->release();
}

const std::string& OffscreenRenderer::gl_version() const { return impl_->version; }
const std::string& OffscreenRenderer::gl_renderer() const { return impl_->renderer; }
int OffscreenRenderer::width_px() const { return impl_->width_px; }
int OffscreenRenderer::height_px() const { return impl_->height_px; }

MeshHandle OffscreenRenderer::add_triangles(const std::vector<MeshVertex>& vertices) {
  impl_->make_current();
  std::vector<float> data;
  data.reserve(vertices.size() * 9);
  for (const auto& v : vertices) {
    append(data, v.position_m);
    append(data, v.normal);
    append(data, v.colour);
  }
  VertexBuffer buffer = make_buffer({3, 3, 3});
  upload(buffer, data, static_cast<GLsizei>(vertices.size()), GL_STATIC_DRAW);
  impl_->meshes.push_back(buffer);
  return static_cast<MeshHandle>(impl_->meshes.size() - 1);
}

MeshHandle OffscreenRenderer::add_line_strip(const std::vector<LineVertex>& vertices) {
  impl_->make_current();
  std::vector<float> data;
  data.reserve(vertices.size() * 6);
  for (const auto& v : vertices) {
    append(data, v.position_m);
    append(data, v.colour);
  }
  VertexBuffer buffer = make_buffer({3, 3});
  upload(buffer, data, static_cast<GLsizei>(vertices.size()), GL_STATIC_DRAW);
  impl_->lines.push_back(buffer);
  return static_cast<MeshHandle>(impl_->lines.size() - 1);
}

void OffscreenRenderer::draw(const FrameDrawList& frame, RgbImage& out) {
  Impl& s = *impl_;
  s.make_current();
  const Eigen::Matrix4f view_projection = frame.projection * frame.view;

  glClearColor(frame.background.x(), frame.background.y(), frame.background.z(), 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);

  auto draw_list = [&](GLuint program, const std::vector<MeshDraw>& draws, const std::vector<VertexBuffer>& buffers,
                       GLenum mode) {
    glUseProgram(program);
    glUniformMatrix4fv(glGetUniformLocation(program, "view_projection"), 1, GL_FALSE, view_projection.data());
    const GLint model_location = glGetUniformLocation(program, "model");
    const GLint normal_location = glGetUniformLocation(program, "normal_matrix");  // -1 for lines: ignored
    for (const auto& d : draws) {
      if (d.mesh < 0 || static_cast<std::size_t>(d.mesh) >= buffers.size()) {
        throw std::out_of_range("renderer: unknown mesh handle " + std::to_string(d.mesh));
      }
      const VertexBuffer& b = buffers[static_cast<std::size_t>(d.mesh)];
      const GLsizei count = d.vertex_count < 0 ? b.count : std::min<GLsizei>(d.vertex_count, b.count);
      if (count <= 0) continue;
      glUniformMatrix4fv(model_location, 1, GL_FALSE, d.model.data());
      if (normal_location >= 0) {
        // Normals of a stretched surface transform with the inverse transpose.
        const Eigen::Matrix3f normal_matrix = d.model.topLeftCorner<3, 3>().inverse().transpose();
        glUniformMatrix3fv(normal_location, 1, GL_FALSE, normal_matrix.data());
      }
      glBindVertexArray(b.vao);
      glDrawArrays(mode, 0, count);
    }
  };

  glUseProgram(s.mesh_program);
  glUniform1i(glGetUniformLocation(s.mesh_program, "orthographic"), frame.orthographic ? 1 : 0);
  glUniform3fv(glGetUniformLocation(s.mesh_program, "eye"), 1, frame.eye_m.data());
  glUniform3fv(glGetUniformLocation(s.mesh_program, "to_viewer"), 1, frame.to_viewer.data());
  glUniform3fv(glGetUniformLocation(s.mesh_program, "to_light"), 1, frame.to_light.data());
  draw_list(s.mesh_program, frame.meshes, s.meshes, GL_TRIANGLES);
  draw_list(s.line_program, frame.line_strips, s.lines, GL_LINE_STRIP);

  glDisable(GL_DEPTH_TEST);
  if (!frame.markers.empty()) {
    std::vector<float> data;
    data.reserve(frame.markers.size() * 8);
    for (const auto& m : frame.markers) {
      append(data, m.position_m);
      append(data, m.colour);
      data.push_back(m.diameter_px);
      data.push_back(m.ring ? 1.0f : 0.0f);
    }
    upload(s.markers, data, static_cast<GLsizei>(frame.markers.size()), GL_STREAM_DRAW);
    glUseProgram(s.marker_program);
    glUniformMatrix4fv(glGetUniformLocation(s.marker_program, "view_projection"), 1, GL_FALSE,
                       view_projection.data());
    glBindVertexArray(s.markers.vao);
    glDrawArrays(GL_POINTS, 0, s.markers.count);
  }
  if (!frame.overlay.empty()) {
    std::vector<float> data;
    data.reserve(frame.overlay.size() * 5);
    for (const auto& v : frame.overlay) {
      data.insert(data.end(), {v.position_px.x(), v.position_px.y()});
      append(data, v.colour);
    }
    upload(s.overlay, data, static_cast<GLsizei>(frame.overlay.size()), GL_STREAM_DRAW);
    glUseProgram(s.overlay_program);
    glUniform2f(glGetUniformLocation(s.overlay_program, "viewport_px"), static_cast<float>(s.width_px),
                static_cast<float>(s.height_px));
    glBindVertexArray(s.overlay.vao);
    glDrawArrays(GL_TRIANGLES, 0, s.overlay.count);
  }
  glBindVertexArray(0);
  glFinish();  // OSMesa's buffer holds the picture once GL is done

  // OSMesa rows start at the bottom of the picture; PNG rows at the top.
  out.width_px = s.width_px;
  out.height_px = s.height_px;
  out.rgb.resize(static_cast<std::size_t>(s.width_px) * static_cast<std::size_t>(s.height_px) * 3);
  const std::size_t w = static_cast<std::size_t>(s.width_px);
  for (std::size_t row = 0; row < static_cast<std::size_t>(s.height_px); ++row) {
    const unsigned char* src = s.rgba.data() + (static_cast<std::size_t>(s.height_px) - 1 - row) * w * 4;
    unsigned char* dst = out.rgb.data() + row * w * 3;
    for (std::size_t x = 0; x < w; ++x) {
      dst[3 * x + 0] = src[4 * x + 0];
      dst[3 * x + 1] = src[4 * x + 1];
      dst[3 * x + 2] = src[4 * x + 2];
    }
  }
}

}  // namespace railjoint
