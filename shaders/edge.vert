#version 450
// B-rep edge lines: line-list positions, transformed by the instance.
#extension GL_GOOGLE_include_directive : require
#include "shared.h"
#include "common.glsl"

layout(location = 0) in vec3 inPosition;

void main() {
  gl_Position = globals.viewProj * (instances[draw.instance].model * vec4(inPosition, 1.0));
}
