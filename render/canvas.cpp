#include "render/canvas.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>

#include "render/internal/font.h"
#include "render/internal/gl_api.h"
#include "render/internal/tessellate.h"

namespace canopy::render {
namespace {

std::atomic<int> contexts_created{0};

// Positions arrive in image pixels (top-left origin, y down).
constexpr const char* kVertexShader = R"(#version 120
attribute vec2 a_position;
attribute vec4 a_shape;
attribute float a_scale;
attribute vec4 a_colour;
attribute vec4 a_edge_colour;
uniform vec2 u_size;
varying vec4 v_shape;
varying float v_scale;
varying vec4 v_colour;
varying vec4 v_edge_colour;
void main() {
  gl_Position = vec4(2.0 * a_position.x / u_size.x - 1.0, 1.0 - 2.0 * a_position.y / u_size.y, 0.0, 1.0);
  v_shape = a_shape;
  v_scale = a_scale;
  v_colour = a_colour;
  v_edge_colour = a_edge_colour;
}
)";

// Solid triangles: every fragment whose centre is inside, in one colour.
constexpr const char* kSolidShader = R"(#version 120
varying vec4 v_colour;
void main() {
  gl_FragColor = v_colour;
}
)";

// Round quads (internal/tessellate.h): r = |(u, v)| in units of the outer radius R = v_scale px.
// Smooth: each edge's coverage is the clamped signed distance to it in px, plus ½ (a linear
// ramp one pixel wide centred on the edge). Exact (masks): covered or not at the pixel centre.
constexpr const char* kRoundShader = R"(#version 120
uniform float u_smooth;
varying vec4 v_shape;
varying float v_scale;
varying vec4 v_colour;
varying vec4 v_edge_colour;
void main() {
  float r = length(v_shape.xy);
  float outer, inner, band;
  if (u_smooth > 0.5) {
    outer = clamp((1.0 - r) * v_scale + 0.5, 0.0, 1.0);
    inner = clamp((r - v_shape.z) * v_scale + 0.5, 0.0, 1.0);
    band = clamp((r - v_shape.w) * v_scale + 0.5, 0.0, 1.0);
  } else {
    outer = r <= 1.0 ? 1.0 : 0.0;
    inner = r >= v_shape.z ? 1.0 : 0.0;
    band = r >= v_shape.w ? 1.0 : 0.0;
  }
  float coverage = outer * inner;
  if (coverage <= 0.0) discard;
  vec4 colour = mix(v_colour, v_edge_colour, band);
  gl_FragColor = vec4(colour.rgb, colour.a * coverage);
}
)";

// Attribute locations, bound before linking, shared by both programs.
constexpr GLuint kPosition = 0, kShape = 1, kScale = 2, kColour = 3, kEdgeColour = 4;

GLuint compile(const internal::GlApi& gl, GLenum kind, const char* source) {
  const GLuint shader = gl.CreateShader(kind);
  gl.ShaderSource(shader, 1, &source, nullptr);
  gl.CompileShader(shader);
  GLint ok = GL_FALSE;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[1024] = {};
    gl.GetShaderInfoLog(shader, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("OSMesa: shader does not compile: ") + log);
  }
  return shader;
}

GLuint link(const internal::GlApi& gl, const char* fragment_source) {
  const GLuint program = gl.CreateProgram();
  const GLuint vs = compile(gl, GL_VERTEX_SHADER, kVertexShader);
  const GLuint fs = compile(gl, GL_FRAGMENT_SHADER, fragment_source);
  gl.AttachShader(program, vs);
  gl.AttachShader(program, fs);
  gl.BindAttribLocation(program, kPosition, "a_position");
  gl.BindAttribLocation(program, kShape, "a_shape");
  gl.BindAttribLocation(program, kScale, "a_scale");
  gl.BindAttribLocation(program, kColour, "a_colour");
  gl.BindAttribLocation(program, kEdgeColour, "a_edge_colour");
  gl.LinkProgram(program);
  gl.DeleteShader(vs);
  gl.DeleteShader(fs);
  GLint ok = GL_FALSE;
  gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) throw std::runtime_error("OSMesa: shader program does not link");
  return program;
}

enum class Pass { frame, mask };

}  // namespace

int glContextsCreated() {
  return contexts_created.load();
}

struct Canvas::Gl {
  const internal::GlApi& gl = internal::glApi();  // loads OSMesa on the first canvas that draws
  OSMesaContext context = nullptr;
  ImageSize size;
  std::vector<std::uint8_t> buffer;  // OSMesa's: RGBA, rows from the bottom
  GLuint solid = 0, round = 0, vbo = 0;
  GLint smooth_uniform = -1;
  std::size_t vbo_bytes = 0;  // capacity of the vertex buffer, grown (never shrunk) as needed
  internal::Mesh mesh;

  explicit Gl(ImageSize image) : size(image) {
    buffer.assign(static_cast<std::size_t>(size.width) * size.height * 4, 0);
    context = gl.OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
    if (!context) throw std::runtime_error("OSMesa: cannot create a GL context");
    ++contexts_created;
    makeCurrent();
    solid = link(gl, kSolidShader);
    round = link(gl, kRoundShader);
    for (const GLuint program : {solid, round}) {
      gl.UseProgram(program);
      gl.Uniform2f(gl.GetUniformLocation(program, "u_size"), static_cast<float>(size.width),
                   static_cast<float>(size.height));
    }
    smooth_uniform = gl.GetUniformLocation(round, "u_smooth");
    gl.GenBuffers(1, &vbo);
    gl.BindBuffer(GL_ARRAY_BUFFER, vbo);
    const auto stride = static_cast<GLsizei>(sizeof(internal::Vertex));
    const auto at = [](std::size_t offset) { return reinterpret_cast<const void*>(offset); };
    for (const GLuint a : {kPosition, kShape, kScale, kColour, kEdgeColour})
      gl.EnableVertexAttribArray(a);
    gl.VertexAttribPointer(kPosition, 2, GL_FLOAT, GL_FALSE, stride,
                           at(offsetof(internal::Vertex, x)));
    gl.VertexAttribPointer(kShape, 4, GL_FLOAT, GL_FALSE, stride,
                           at(offsetof(internal::Vertex, u)));
    gl.VertexAttribPointer(kScale, 1, GL_FLOAT, GL_FALSE, stride,
                           at(offsetof(internal::Vertex, scale)));
    gl.VertexAttribPointer(kColour, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride,
                           at(offsetof(internal::Vertex, rgba)));
    gl.VertexAttribPointer(kEdgeColour, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride,
                           at(offsetof(internal::Vertex, edge_rgba)));
    gl.Viewport(0, 0, size.width, size.height);
    gl.Disable(GL_DEPTH_TEST);
    gl.Disable(GL_DITHER);
  }

  ~Gl() { gl.OSMesaDestroyContext(context); }

  void makeCurrent() {
    if (gl.OSMesaGetCurrentContext() == context) return;
    if (!gl.OSMesaMakeCurrent(context, buffer.data(), GL_UNSIGNED_BYTE, size.width, size.height)) {
      throw std::runtime_error("OSMesa: cannot make the GL context current");
    }
  }

  // Clears to `clear` and draws the mesh batch by batch. A frame blends "over" where a batch
  // needs it and not where it is opaque (the same result, faster); a mask adds every fragment.
  void drawMesh(const Rgba& clear, Pass pass) {
    makeCurrent();
    gl.ClearColor(clear.r / 255.0f, clear.g / 255.0f, clear.b / 255.0f, clear.a / 255.0f);
    gl.Clear(GL_COLOR_BUFFER_BIT);
    if (!mesh.vertices.empty()) {
      // Refill the same storage: a new buffer each frame would page-fault its memory anew.
      const std::size_t bytes = mesh.vertices.size() * sizeof(internal::Vertex);
      if (bytes > vbo_bytes) {
        vbo_bytes = std::max(bytes, 2 * vbo_bytes);
        gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vbo_bytes), nullptr,
                      GL_DYNAMIC_DRAW);
      }
      gl.BufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes), mesh.vertices.data());
    }
    gl.UseProgram(round);
    gl.Uniform1f(smooth_uniform, pass == Pass::frame ? 1.0f : 0.0f);
    if (pass == Pass::mask) {
      gl.Enable(GL_BLEND);
      gl.BlendFunc(GL_ONE, GL_ONE);
    } else {
      gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    }
    GLuint current = round;
    for (const internal::Batch& batch : mesh.batches) {
      if (pass == Pass::frame) batch.blend ? gl.Enable(GL_BLEND) : gl.Disable(GL_BLEND);
      const GLuint wanted = batch.round ? round : solid;
      if (wanted != current) gl.UseProgram(current = wanted);
      gl.DrawArrays(GL_TRIANGLES, batch.first, batch.count);
    }
    gl.Finish();
  }
};

Canvas::Canvas(ImageSize size) : size_(size) {
  if (size.width < 1 || size.height < 1 || size.width > kMaxCanvasSide ||
      size.height > kMaxCanvasSide) {
    throw std::invalid_argument("Canvas: size " + std::to_string(size.width) + "x" +
                                std::to_string(size.height) + " is out of range");
  }
}

Canvas::~Canvas() = default;
Canvas::Canvas(Canvas&&) noexcept = default;
Canvas& Canvas::operator=(Canvas&&) noexcept = default;

Canvas::Gl& Canvas::gl() {
  if (!gl_) gl_ = std::make_unique<Gl>(size_);
  return *gl_;
}

void Canvas::draw(const Scene& scene, Image& out) {
  if (!(scene.viewport.size == size_)) {
    throw std::invalid_argument("Canvas::draw: viewport size differs from the canvas");
  }
  Gl& g = gl();
  g.mesh.clear();
  internal::tessellate(scene, g.mesh);
  g.drawMesh(scene.background, Pass::frame);
  // OSMesa's RGBA rows run from the bottom; the image's RGB rows from the top.
  const int w = size_.width, h = size_.height;
  out.size = size_;
  out.rgb.resize(static_cast<std::size_t>(w) * h * 3);
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* row = g.buffer.data() + static_cast<std::size_t>(h - 1 - y) * w * 4;
    std::uint8_t* dst = out.rgb.data() + static_cast<std::size_t>(y) * w * 3;
    for (int x = 0; x < w; ++x) {
      dst[3 * x] = row[4 * x];
      dst[3 * x + 1] = row[4 * x + 1];
      dst[3 * x + 2] = row[4 * x + 2];
    }
  }
  // Text over everything, anti-aliased by FreeType (tessellate() left it out).
  if (internal::Font* font = internal::Font::instance()) {
    for (const Primitive& p : scene.world) {
      if (const auto* t = std::get_if<Text>(&p))
        font->draw(out, scene.viewport.toPixel(t->at) + t->offset_px, t->text, t->scale, t->colour);
    }
    for (const Primitive& p : scene.overlay) {
      if (const auto* t = std::get_if<Text>(&p))
        font->draw(out, t->at + t->offset_px, t->text, t->scale, t->colour);
    }
  }
}

Image Canvas::draw(const Scene& scene) {
  Image image;
  draw(scene, image);
  return image;
}

const std::vector<std::uint8_t>& Canvas::accumulate(const Scene& scene) {
  if (!(scene.viewport.size == size_)) {
    throw std::invalid_argument("Canvas::accumulate: viewport size differs from the canvas");
  }
  Gl& g = gl();
  g.mesh.clear();
  internal::tessellate(scene, g.mesh);
  g.drawMesh(Rgba{0, 0, 0, 0}, Pass::mask);
  const int w = size_.width, h = size_.height;
  mask_.resize(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* row = g.buffer.data() + static_cast<std::size_t>(h - 1 - y) * w * 4;
    std::uint8_t* dst = mask_.data() + static_cast<std::size_t>(y) * w;
    for (int x = 0; x < w; ++x) dst[x] = row[4 * x];
  }
  return mask_;
}

}  // namespace canopy::render
