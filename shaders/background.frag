#version 450
// Soft vertical gradient behind the model, interpolated from the vertices (one add per pixel:
// the background covers every pixel, so it must be cheap on software rasterisers).
#extension GL_GOOGLE_include_directive : require
#include "shared.h"
#include "common.glsl"

layout(location = 0) in vec3 inColor;
layout(location = 0) out vec4 outColor;

void main() {
  outColor = toTarget(inColor);
}
