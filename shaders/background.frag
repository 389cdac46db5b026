#version 450
// Soft vertical gradient behind the model.
#extension GL_GOOGLE_include_directive : require
#include "shared.h"
#include "common.glsl"

layout(location = 0) in float inHeight;
layout(location = 0) out vec4 outColor;

void main() {
  // Smoothstep keeps the gradient calm at both ends instead of a linear ramp's visible kinks.
  float t = smoothstep(0.0, 1.0, clamp(inHeight, 0.0, 1.0));
  outColor = toTarget(mix(globals.backgroundBottom.rgb, globals.backgroundTop.rgb, t));
}
