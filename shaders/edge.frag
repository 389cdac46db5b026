#version 450
// B-rep edge lines in one colour.
#extension GL_GOOGLE_include_directive : require
#include "shared.h"
#include "common.glsl"

layout(location = 0) out vec4 outColor;

void main() {
  outColor = toTarget(globals.edgeColor.rgb);
}
