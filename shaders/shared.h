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
#define CETVIEW_SPEC_ENCODE_SRGB 0  // the target is UNORM: shaders encode sRGB themselves
#define CETVIEW_SPEC_TWO_SIDED 1    // faces seen from behind are lit as their front (not culled solids)

// The light rig, fixed to the camera and so constant in view space (x right, y up, z towards the
// eye): a headlight along the view axis, a key light from the upper left in front of the model,
// hemisphere ambient brighter towards screen-up, a faint specular of the key light. Compile-time
// constants, so the fragment shader's lighting folds to a few multiply-adds: lavapipe spends far
// less on a 1M-triangle frame than with the same vectors read from push constants or a uniform
// buffer. The key light direction is (-0.45, 0.65, 0.62) normalised.
#define CETVIEW_KEY_LIGHT_X (-0.447900)
#define CETVIEW_KEY_LIGHT_Y 0.646966
#define CETVIEW_KEY_LIGHT_Z 0.617106
#define CETVIEW_LIGHT_HEADLIGHT 0.55
#define CETVIEW_LIGHT_KEY 0.42
#define CETVIEW_LIGHT_SKY 0.16
#define CETVIEW_LIGHT_SPECULAR 0.12

// Per frame: what every draw of the frame shares.
struct Globals {
  vec4 backgroundTop;     // gradient colour at the top of the image
  vec4 backgroundBottom;  // gradient colour at the bottom
  vec4 edgeColor;         // B-rep edge lines
};

// Push constants of each draw (one instance of a part). Lighting happens in view space with the
// constant light rig above: the vertex shader turns each normal into view space with
// normalToView, and the fragment shader reads nothing per draw but the colour. Exact for rigid and
// uniformly scaled instances (their normals turn with the same rotation), which is every placement
// a CAD assembly can express (gp_Trsf has no non-uniform scale), mirrored ones included.
// The viewer is at infinity (OpenGL's default light model): the headlight and the specular use
// the view axis, not the ray to each pixel. That saves an interpolated position per triangle,
// a quarter of the frame on software rasterisers, and is invisible at CAD fields of view.
struct DrawConstants {
  mat4 modelViewProj;  // part space -> clip space (Vulkan: y down, depth 0..1)
  vec4 normalToView0;  // xyz: the columns of the part -> view rotation for normals (unit scale);
  vec4 normalToView1;  //      w unused
  vec4 normalToView2;
  vec4 color;  // linear RGBA used for every face when a >= 0; a < 0: the per-face colours
               // (the *_pushed face shaders: always a colour, the current run's)
};

#ifdef __cplusplus
}  // namespace cetview::gpu
#endif

#endif  // CETVIEW_SHADERS_SHARED_H
