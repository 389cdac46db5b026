#version 450
// Faces: one indirect draw per face with firstInstance = face id, so gl_InstanceIndex names the
// face and its colour travels to the fragment shader as a flat varying; or, built with
// CETVIEW_COLOR_PUSHED (mesh_pushed_vert), runs of faces of one colour whose colour the fragment
// shader reads from draw.color, so there is no colour varying (software rasterisers set up and
// store every varying per triangle). The normal goes into view space, where the lights are
// constant (shared.h).
#extension GL_GOOGLE_include_directive : require
#include "shared.h"
#include "common.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;

layout(location = 0) out vec3 outNormal;
#ifndef CETVIEW_COLOR_PUSHED
layout(location = 1) flat out vec3 outColor;
#endif

void main() {
  gl_Position = draw.modelViewProj * vec4(inPosition, 1.0);
  outNormal = mat3(draw.normalToView0.xyz, draw.normalToView1.xyz, draw.normalToView2.xyz) * inNormal;
#ifndef CETVIEW_COLOR_PUSHED
  if (draw.color.a >= 0.0) {
    outColor = draw.color.rgb;
  } else {
    outColor = srgbToLinear(unpackUnorm4x8(faceColors[gl_InstanceIndex]).rgb);
  }
#endif
}
