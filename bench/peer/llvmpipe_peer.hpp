#pragma once
// The peer a user would pick: Mesa's llvmpipe through EGL surfaceless (no window, no pbuffer), an
// OpenGL 3.3 core context drawing into a framebuffer object. It renders a parashade Scene with the
// same meshes, camera, projection, lights, materials and resolution:
//   gouraud — Blinn–Phong per vertex in the vertex shader, smooth (perspective-correct) interpolation;
//   phong   — Blinn–Phong per pixel in the fragment shader from interpolated world position and normal.
// The lighting formula is kernels/blinn_phong.h's (and lighting.cpp's): ambient + sum over lights of
// I_l (k_d max(0, N.L) + k_s max(0, N.H)^n), specular independent of N.L, no attenuation.
// Geometry conventions are made to agree with parashade's (screen_geometry.hpp): the projection gets a
// y flip so that GL's window y runs down the image like parashade's (the same float window coordinates,
// row 0 at the top, no read-back flip); front faces are counter-clockwise in parashade's NDC, which is
// clockwise after the flip (glFrontFace(GL_CW)); back faces are culled exactly when the scene says so.
// LP_NUM_THREADS must be set before the first EGL call (Mesa reads it when the driver loads).
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "parashade/image.hpp"
#include "parashade/method.hpp"
#include "parashade/scene.hpp"

namespace parashade::peer {

struct PeerInfo {
  std::string renderer, version, vendor;  // GL_RENDERER, GL_VERSION, GL_VENDOR
};

class LlvmpipePeer {
 public:
  // Opens EGL surfaceless and an OpenGL 3.3 core context; throws std::runtime_error when unavailable.
  LlvmpipePeer();
  ~LlvmpipePeer();
  LlvmpipePeer(const LlvmpipePeer&) = delete;
  LlvmpipePeer& operator=(const LlvmpipePeer&) = delete;

  const PeerInfo& info() const { return info_; }
  // Uploads the scene's meshes into vertex buffers (once per scene; not part of a frame).
  void load(const Scene& scene);
  // One frame of the loaded scene: clear, draw every object, glReadPixels into `out` (which waits for
  // the rasterizer). Alpha is 255 where some triangle covered the pixel, 0 elsewhere (as parashade's).
  void render(const Scene& scene, Method method, RenderedImage& out);

 private:
  struct ObjectBuffers {
    unsigned vao = 0, positions = 0, normals = 0, indices = 0;
    int index_count = 0;
  };
  void ensure_framebuffer(int width, int height);
  unsigned program(Method method, const Scene& scene);
  void release_scene();

  void* display_ = nullptr;
  void* context_ = nullptr;
  PeerInfo info_;
  unsigned fbo_ = 0, colour_rb_ = 0, depth_rb_ = 0;
  int fb_width_ = 0, fb_height_ = 0;
  const Scene* loaded_ = nullptr;
  std::vector<ObjectBuffers> objects_;
  std::map<std::string, unsigned> programs_;  // by method and light configuration
};

}  // namespace parashade::peer
