#pragma once
// Everything a program needs to build or load a scene, render it on an OpenCL device, measure its error
// and write the image: #include <parashade/parashade.hpp> and link parashade::parashade (README, "Using
// parashade from another program"). The pipeline's stages, the units' golden models and the studies have
// headers of their own beside this one.
#include "parashade/version.hpp"
#include "parashade/errors.hpp"

// Scenes: meshes, procedural shapes, JSON scene files.
#include "parashade/mesh.hpp"
#include "parashade/shapes.hpp"
#include "parashade/scene.hpp"
#include "parashade/scene_files.hpp"

// What a frame computes: the method, the modeled shading unit and arithmetic, the Phong family's options.
#include "parashade/method.hpp"
#include "parashade/units.hpp"
#include "parashade/frame_config.hpp"
#include "parashade/combinations.hpp"

// Rendering on OpenCL devices, and the frame's image.
#include "parashade/device.hpp"
#include "parashade/renderer.hpp"
#include "parashade/split_renderer.hpp"
#include "parashade/command_files.hpp"
#include "parashade/render_step.hpp"
#include "parashade/render_report.hpp"
#include "parashade/render_outputs.hpp"
#include "parashade/image.hpp"

// The exact double-precision reference and error metrics.
#include "parashade/reference.hpp"
#include "parashade/metrics.hpp"
