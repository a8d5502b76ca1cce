#include "llvmpipe_peer.hpp"

#include <stdexcept>

#define EGL_EGLEXT_PROTOTYPES
#include <EGL/egl.h>
#include <EGL/eglext.h>
#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "parashade/geometry_stage.hpp"

namespace parashade::peer {
namespace {

[[noreturn]] void fail(const std::string& what) { throw std::runtime_error("llvmpipe peer: " + what); }

// The lighting of kernels/blinn_phong.h in GLSL, in [0,1] units (the kernels work in levels x255).
const char* kLighting = R"(
uniform vec3 ambient;        // k_a x colour x I_a
uniform vec3 diffuse;        // k_d x colour
uniform vec3 specular;       // k_s x specular colour
uniform float shininess;
uniform vec3 eye;            // LOCAL_VIEWER: eye position, else the unit vector toward the viewer
uniform vec3 light_vec[NUM_LIGHTS];   // point: position; directional: unit vector toward the light
uniform vec3 light_colour[NUM_LIGHTS];
vec3 blinn_phong(vec3 p, vec3 n) {
#if LOCAL_VIEWER
  vec3 v = normalize(eye - p);
#else
  vec3 v = eye;
#endif
  vec3 c = ambient;
  for (int i = 0; i < NUM_LIGHTS; ++i) {
    vec3 l = ((POINT_LIGHTS >> i) & 1) != 0 ? normalize(light_vec[i] - p) : light_vec[i];
    float n_dot_l = max(dot(n, l), 0.0);
    float n_dot_h = max(dot(n, normalize(l + v)), 0.0);
    c += light_colour[i] * (diffuse * n_dot_l + specular * pow(n_dot_h, shininess));
  }
  return c;
}
)";

const char* kGouraudVertex = R"(
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 clip_from_object;
uniform mat4 world_from_object;
uniform mat3 normal_matrix;
out vec3 colour;
void main() {
  vec3 p = (world_from_object * vec4(position, 1.0)).xyz;
  colour = blinn_phong(p, normalize(normal_matrix * normal));
  gl_Position = clip_from_object * vec4(position, 1.0);
}
)";
const char* kGouraudFragment = R"(
in vec3 colour;
out vec4 frag;
void main() { frag = vec4(colour, 1.0); }
)";
const char* kPhongVertex = R"(
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 clip_from_object;
uniform mat4 world_from_object;
uniform mat3 normal_matrix;
out vec3 world;
out vec3 world_normal;
void main() {
  world = (world_from_object * vec4(position, 1.0)).xyz;
  world_normal = normal_matrix * normal;
  gl_Position = clip_from_object * vec4(position, 1.0);
}
)";
const char* kPhongFragment = R"(
in vec3 world;
in vec3 world_normal;
out vec4 frag;
void main() { frag = vec4(blinn_phong(world, normalize(world_normal)), 1.0); }
)";

unsigned compile(GLenum type, const std::string& source) {
  const GLuint s = glCreateShader(type);
  const char* text = source.c_str();
  glShaderSource(s, 1, &text, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    fail(std::string("shader does not compile: ") + log);
  }
  return s;
}

// Front faces are counter-clockwise in NDC; the y flip below makes them clockwise for GL.
glm::mat4 y_flip() {
  glm::mat4 m(1.0f);
  m[1][1] = -1.0f;
  return m;
}

}  // namespace

LlvmpipePeer::LlvmpipePeer() {
  EGLDisplay d = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (d == EGL_NO_DISPLAY) fail("no EGL surfaceless display (EGL_MESA_platform_surfaceless)");
  EGLint major = 0, minor = 0;
  if (!eglInitialize(d, &major, &minor)) fail("eglInitialize failed");
  display_ = d;
  if (!eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API) failed");
  const EGLint config_attrs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  eglChooseConfig(d, config_attrs, &config, 1, &configs);  // surfaceless: a config is optional
  const EGLint context_attrs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                  EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext c = eglCreateContext(d, configs ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, context_attrs);
  if (c == EGL_NO_CONTEXT) fail("no OpenGL 3.3 core context");
  context_ = c;
  if (!eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, c)) fail("eglMakeCurrent without a surface failed");
  info_.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  info_.version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  info_.vendor = reinterpret_cast<const char*>(glGetString(GL_VENDOR));
}

LlvmpipePeer::~LlvmpipePeer() {
  release_scene();
  for (auto& [key, p] : programs_) glDeleteProgram(p);
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
  if (colour_rb_) glDeleteRenderbuffers(1, &colour_rb_);
  if (depth_rb_) glDeleteRenderbuffers(1, &depth_rb_);
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  eglTerminate(display_);
}

void LlvmpipePeer::release_scene() {
  for (ObjectBuffers& o : objects_) {
    glDeleteVertexArrays(1, &o.vao);
    GLuint buffers[] = {o.positions, o.normals, o.indices};
    glDeleteBuffers(3, buffers);
  }
  objects_.clear();
  loaded_ = nullptr;
}

void LlvmpipePeer::load(const Scene& scene) {
  release_scene();
  for (const Object& obj : scene.objects) {
    const Mesh& m = *obj.mesh;
    ObjectBuffers o;
    glGenVertexArrays(1, &o.vao);
    glBindVertexArray(o.vao);
    GLuint buffers[3];
    glGenBuffers(3, buffers);
    o.positions = buffers[0];
    o.normals = buffers[1];
    o.indices = buffers[2];
    glBindBuffer(GL_ARRAY_BUFFER, o.positions);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(m.positions.size() * sizeof(glm::vec3)), m.positions.data(), GL_STATIC_DRAW);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glEnableVertexAttribArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, o.normals);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(m.normals.size() * sizeof(glm::vec3)), m.normals.data(), GL_STATIC_DRAW);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glEnableVertexAttribArray(1);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, o.indices);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(m.triangles.size() * sizeof(glm::uvec3)), m.triangles.data(),
                 GL_STATIC_DRAW);
    o.index_count = int(3 * m.triangles.size());
    objects_.push_back(o);
  }
  glBindVertexArray(0);
  glFinish();
  loaded_ = &scene;
}

void LlvmpipePeer::ensure_framebuffer(int width, int height) {
  if (fbo_ && width == fb_width_ && height == fb_height_) return;
  if (!fbo_) {
    glGenFramebuffers(1, &fbo_);
    glGenRenderbuffers(1, &colour_rb_);
    glGenRenderbuffers(1, &depth_rb_);
  }
  glBindRenderbuffer(GL_RENDERBUFFER, colour_rb_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_rb_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_rb_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_rb_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) fail("framebuffer incomplete");
  fb_width_ = width;
  fb_height_ = height;
}

unsigned LlvmpipePeer::program(Method method, const Scene& scene) {
  if (method != Method::gouraud && method != Method::phong) fail("only gouraud and phong have a peer");
  if (scene.lights.empty()) fail("a scene without lights has no peer here");
  int point_mask = 0;
  for (std::size_t i = 0; i < scene.lights.size(); ++i)
    if (scene.lights[i].type == LightType::point) point_mask |= 1 << i;
  const bool local = scene.local_viewer && scene.camera.projection == Projection::perspective;
  const std::string defines = "#version 330 core\n#define NUM_LIGHTS " + std::to_string(scene.lights.size()) +
                              "\n#define POINT_LIGHTS " + std::to_string(point_mask) + "\n#define LOCAL_VIEWER " +
                              (local ? "1" : "0") + "\n";
  const std::string key = std::string(method_name(method)) + "|" + defines;
  auto it = programs_.find(key);
  if (it != programs_.end()) return it->second;
  const bool gouraud = method == Method::gouraud;
  const GLuint vs = compile(GL_VERTEX_SHADER, defines + (gouraud ? kLighting : "") +
                                                  (gouraud ? kGouraudVertex : kPhongVertex));
  const GLuint fs = compile(GL_FRAGMENT_SHADER, defines + (gouraud ? "" : kLighting) +
                                                    (gouraud ? kGouraudFragment : kPhongFragment));
  const GLuint p = glCreateProgram();
  glAttachShader(p, vs);
  glAttachShader(p, fs);
  glLinkProgram(p);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) fail("program does not link");
  programs_[key] = p;
  return p;
}

void LlvmpipePeer::render(const Scene& scene, Method method, RenderedImage& out) {
  if (loaded_ != &scene) load(scene);
  ensure_framebuffer(scene.width, scene.height);
  const GLuint p = program(method, scene);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, scene.width, scene.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);  // ties: the earlier triangle wins, as parashade's depth test
  if (scene.cull_backfaces) {
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CW);
  } else {
    glDisable(GL_CULL_FACE);
  }
  glClearColor(scene.background.r, scene.background.g, scene.background.b, 0.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glUseProgram(p);

  const Camera& cam = scene.camera;
  const bool local = scene.local_viewer && cam.projection == Projection::perspective;
  const glm::vec3 eye = local ? cam.position : glm::normalize(cam.position - cam.target);
  glUniform3fv(glGetUniformLocation(p, "eye"), 1, glm::value_ptr(eye));
  std::vector<glm::vec3> light_vec, light_colour;
  for (const Light& l : scene.lights) {
    light_vec.push_back(l.type == LightType::point ? l.position : -glm::normalize(l.direction));
    light_colour.push_back(l.color);
  }
  glUniform3fv(glGetUniformLocation(p, "light_vec"), GLsizei(light_vec.size()), glm::value_ptr(light_vec[0]));
  glUniform3fv(glGetUniformLocation(p, "light_colour"), GLsizei(light_colour.size()), glm::value_ptr(light_colour[0]));
  const glm::mat4 clip_from_world = y_flip() * view_projection(scene);
  const GLint loc_clip = glGetUniformLocation(p, "clip_from_object"), loc_world = glGetUniformLocation(p, "world_from_object"),
              loc_normal = glGetUniformLocation(p, "normal_matrix"), loc_amb = glGetUniformLocation(p, "ambient"),
              loc_kd = glGetUniformLocation(p, "diffuse"), loc_ks = glGetUniformLocation(p, "specular"),
              loc_n = glGetUniformLocation(p, "shininess");
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Object& obj = scene.objects[i];
    const Material& m = scene.materials.at(obj.material);
    const glm::mat4 clip = clip_from_world * obj.model;
    const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(obj.model)));
    glUniformMatrix4fv(loc_clip, 1, GL_FALSE, glm::value_ptr(clip));
    glUniformMatrix4fv(loc_world, 1, GL_FALSE, glm::value_ptr(obj.model));
    glUniformMatrix3fv(loc_normal, 1, GL_FALSE, glm::value_ptr(normal_matrix));
    const glm::vec3 amb = m.ambient * scene.ambient_light;
    glUniform3fv(loc_amb, 1, glm::value_ptr(amb));
    glUniform3fv(loc_kd, 1, glm::value_ptr(m.diffuse));
    glUniform3fv(loc_ks, 1, glm::value_ptr(m.specular));
    glUniform1f(loc_n, m.shininess);
    glBindVertexArray(objects_[i].vao);
    glDrawElements(GL_TRIANGLES, objects_[i].index_count, GL_UNSIGNED_INT, nullptr);
  }
  glBindVertexArray(0);
  out.width = scene.width;
  out.height = scene.height;
  out.rgba.resize(std::size_t(scene.width) * scene.height * 4);
  out.rgb_float.clear();
  // Row 0 of the read-back is GL's window row 0, which the y flip made the top row.
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, scene.width, scene.height, GL_RGBA, GL_UNSIGNED_BYTE, out.rgba.data());
  if (glGetError() != GL_NO_ERROR) fail("a GL call failed during the frame");
}

}  // namespace parashade::peer
