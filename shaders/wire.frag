#version 450
// Wireframe of the triangle edges (polygon mode LINE): the face colour, a little darker so thin
// lines stay readable on the light background.
#extension GL_GOOGLE_include_directive : require
#include "shared.h"
#include "common.glsl"

layout(location = 0) in vec3 inNormal;  // unused; declared so the interface matches mesh.vert
layout(location = 1) flat in vec3 inColor;

layout(location = 0) out vec4 outColor;

void main() {
  vec3 color = kColorPushed ? draw.color.rgb : inColor;
  outColor = toTarget(color * 0.6);
}
