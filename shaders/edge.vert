#version 450
// B-rep edge lines: line-list positions in part space.
#extension GL_GOOGLE_include_directive : require
#include "shared.h"
#include "common.glsl"

layout(location = 0) in vec3 inPosition;

void main() {
  gl_Position = draw.modelViewProj * vec4(inPosition, 1.0);
}
