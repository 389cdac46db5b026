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
#define CETVIEW_BINDING_GLOBALS 0    // uniform Globals, one per frame in flight
#define CETVIEW_BINDING_FACES 1      // storage uint[]: per face, packed sRGB RGBA8 (R in the low byte)
#define CETVIEW_BINDING_INSTANCES 2  // storage InstanceData[]

// Globals.flags.x bits.
#define CETVIEW_FLAG_FILE_COLORS 1u   // use per-face / per-instance colours, else defaultFaceColor
#define CETVIEW_FLAG_ORTHOGRAPHIC 2u  // headlight is the view axis, not the ray to the eye
#define CETVIEW_FLAG_ENCODE_SRGB 4u   // target is UNORM: shaders encode sRGB themselves

// InstanceData.flags.x bits.
#define CETVIEW_INSTANCE_COLOR_OVERRIDE 1u  // InstanceData.color replaces the face colours

// DrawConstants.pass values.
#define CETVIEW_PASS_SHADED 0u
#define CETVIEW_PASS_WIREFRAME 1u
#define CETVIEW_PASS_EDGES 2u

// Per frame: camera and look.
struct Globals {
  mat4 viewProj;           // world -> clip (Vulkan clip space: y down, depth 0..1)
  mat4 view;               // world -> view (right-handed, camera looks down -z)
  vec4 backgroundTop;      // gradient colour at the top of the image
  vec4 backgroundBottom;   // gradient colour at the bottom
  vec4 edgeColor;          // B-rep edge lines
  vec4 defaultFaceColor;   // faces when file colours are off or a face has none
  vec4 keyLightDir;        // view space, unit vector towards the key light
  vec4 lightIntensity;     // x headlight, y key light, z ambient (sky), w specular
  uvec4 flags;             // x: CETVIEW_FLAG_* bits
};

// Per instance of a part: transform and optional colour.
struct InstanceData {
  mat4 model;         // part -> world
  mat4 normalMatrix;  // inverse transpose of model (upper 3x3 used)
  vec4 color;         // linear RGBA, used with CETVIEW_INSTANCE_COLOR_OVERRIDE
  uvec4 flags;        // x: CETVIEW_INSTANCE_* bits
};

// Push constants of every draw.
struct DrawConstants {
  uint instance;  // index into InstanceData[]
  uint pass;      // CETVIEW_PASS_*
  uint reserved0;
  uint reserved1;
};

#ifdef __cplusplus
}  // namespace cetview::gpu
#endif

#endif  // CETVIEW_SHADERS_SHARED_H
