#version 450
// Faces: one indirect draw per face with firstInstance = face id, so gl_InstanceIndex names the
// face; or, with kColorPushed, runs of faces of one colour (draw.color), read by the fragment
// shader directly. The normal goes into view space, where the lights are constant (shared.h).
#extension GL_GOOGLE_include_directive : require
#include "shared.h"
#include "common.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;

layout(location = 0) out vec3 outNormal;
layout(location = 1) flat out vec3 outColor;

void main() {
  gl_Position = draw.modelViewProj * vec4(inPosition, 1.0);
  outNormal = mat3(draw.normalToView0.xyz, draw.normalToView1.xyz, draw.normalToView2.xyz) * inNormal;
  if (kColorPushed) {
    outColor = vec3(0.0);  // unread: the fragment shader takes draw.color
  } else if (draw.color.a >= 0.0) {
    outColor = draw.color.rgb;
  } else {
    outColor = srgbToLinear(unpackUnorm4x8(faceColors[gl_InstanceIndex]).rgb);
  }
}
