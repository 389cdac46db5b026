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

// Linear -> sRGB for UNORM targets: the power segment of IEC 61966-2-1 as a minimax fit in c^1/2,
// c^1/4 and c^1/8, within 0.15/255 of the exact curve (an 8-bit result at most one step off);
// three square roots per channel cost a software rasteriser less than pow() or its own sRGB store.
vec3 linearToSrgb(vec3 c) {
  vec3 s1 = sqrt(c);
  vec3 s2 = sqrt(s1);
  vec3 s3 = sqrt(s2);
  vec3 curve = 0.591531888 * s1 + 0.769093895 * s2 - 0.360071117 * s3;
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
