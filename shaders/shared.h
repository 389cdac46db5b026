// GPU structs shared by C++ (engine/) and GLSL (shaders/): one definition, so the layouts cannot drift.
//
// Rules that keep std140 (uniform) and std430 (storage) layouts identical to the C++ ones: members
// are only vec4, uvec4 and mat4, every struct is a multiple of 16 bytes, and C++ static_asserts the
// sizes (engine/gpu_structs.h). Colours are linear RGB unless a name says otherwise.
#ifndef CETVIEW_SHADERS_SHARED_H
#define CETVIEW_SHADERS_SHARED_H

#ifdef __cplusplus
#include <cstdint>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
namespace cetview::gpu {
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
using uint = std::uint32_t;
#endif

// Descriptor set 0 bindings.
#define CETVIEW_BINDING_GLOBALS 0  // uniform Globals, one per frame in flight
#define CETVIEW_BINDING_FACES 1    // storage uint[]: per face, packed sRGB RGBA8 (R in the low byte)

// Specialization constant ids (VkBool32 each), set by every pipeline (engine/pipelines.cpp).
#define CETVIEW_SPEC_COLOR_PUSHED 0  // face colour in DrawConstants::color, none per vertex
#define CETVIEW_SPEC_ENCODE_SRGB 1   // the target is UNORM: shaders encode sRGB themselves

// Per frame: what every draw of the frame shares.
struct Globals {
  vec4 backgroundTop;     // gradient colour at the top of the image
  vec4 backgroundBottom;  // gradient colour at the bottom
  vec4 edgeColor;         // B-rep edge lines
  vec4 lightIntensity;    // x headlight, y key light, z ambient (sky), w specular
};

// Push constants of each draw (one instance of a part). Lighting happens in part space: the CPU
// moves the view direction and the lights into it per instance, so the vertex shader does one
// matrix multiply and passes only the normal on. Exact for rigid and uniformly scaled instances,
// which is every placement a CAD assembly can express (gp_Trsf has no non-uniform scale).
// The viewer is at infinity (OpenGL's default light model): the headlight and the specular use
// the view axis, not the ray to each pixel. That saves an interpolated position per triangle,
// a quarter of the frame on software rasterisers, and is invisible at CAD fields of view.
struct DrawConstants {
  mat4 modelViewProj;  // part space -> clip space (Vulkan: y down, depth 0..1)
  vec4 toEye;          // xyz: unit direction towards the eye; w = 1: light normals facing away from
                       // the eye as their reverse (two-sided), w = 0: no flip (culled closed solids)
  vec4 keyLight;       // xyz: unit direction towards the key light
  vec4 up;             // xyz: unit screen-up direction (the sky of the hemisphere ambient)
  vec4 color;          // linear RGBA used for every face when a >= 0; a < 0: the per-face colours
                       // (with CETVIEW_SPEC_COLOR_PUSHED always a colour: the current run's)
};

#ifdef __cplusplus
}  // namespace cetview::gpu
#endif

#endif  // CETVIEW_SHADERS_SHARED_H
