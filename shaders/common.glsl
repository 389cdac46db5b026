// Declarations every cetview shader shares: the descriptor set, push constants and colour helpers.
// Included after shared.h (GL_GOOGLE_include_directive); the C++ side of each block is in shared.h.
#ifndef CETVIEW_SHADERS_COMMON_GLSL
#define CETVIEW_SHADERS_COMMON_GLSL

layout(set = 0, binding = CETVIEW_BINDING_GLOBALS) uniform GlobalsBlock {
  Globals globals;
};

layout(set = 0, binding = CETVIEW_BINDING_FACES, std430) readonly buffer FaceBlock {
  uint faceColors[];
};

layout(push_constant) uniform PushBlock {
  DrawConstants draw;
};

// Specialization constant CETVIEW_SPEC_ENCODE_SRGB: the target's format is UNORM (see toTarget).
layout(constant_id = CETVIEW_SPEC_ENCODE_SRGB) const bool kEncodeSrgb = false;
// Specialization constant CETVIEW_SPEC_TWO_SIDED: normals facing away from the eye are lit as their
// reverse (open shells, mirrored instances); false for culled closed solids, whose visible
// triangles all face the eye.
layout(constant_id = CETVIEW_SPEC_TWO_SIDED) const bool kTwoSided = true;

// sRGB -> linear: a cubic fit of the IEC 61966-2-1 curve (within 0.3%), cheap enough per vertex
// on software rasterisers where pow() is not.
vec3 srgbToLinear(vec3 c) {
  return c * (c * (c * 0.305306011 + 0.682171111) + 0.012522878);
}

// Linear -> sRGB for UNORM targets: the power segment of IEC 61966-2-1 as a degree-5 minimax
// polynomial in c^1/2, within 0.09/255 of the exact curve (an 8-bit result at most one step off);
// one square root and five multiply-adds per channel cost a software rasteriser less than pow(),
// more square roots, or its own sRGB store.
vec3 linearToSrgb(vec3 c) {
  vec3 t = sqrt(c);
  vec3 curve =
      t * (t * (t * (t * (t * 0.517239188 - 1.623495056) + 2.031424613) - 1.402677422) + 1.517941537) -
      0.040109183;
  return mix(curve, c * 12.92, lessThan(c, vec3(0.0031308)));
}

// Final colour for the target: sRGB targets encode in hardware, UNORM ones need it done here. A
// specialization constant, not a uniform: software rasterisers evaluate both sides of a uniform
// branch this small (an unused pow() per pixel was a tenth of a 1M-triangle frame on lavapipe).
vec4 toTarget(vec3 linearColor) {
  vec3 c = clamp(linearColor, 0.0, 1.0);
  if (kEncodeSrgb) c = linearToSrgb(c);
  return vec4(c, 1.0);
}

#endif  // CETVIEW_SHADERS_COMMON_GLSL
