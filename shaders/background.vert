#version 450
// Full-screen triangle for the background gradient; no vertex buffer (three gl_VertexIndex values).
#extension GL_GOOGLE_include_directive : require
#include "shared.h"
#include "common.glsl"

layout(location = 0) out vec3 outColor;

void main() {
  vec2 p = vec2((gl_VertexIndex == 1) ? 3.0 : -1.0, (gl_VertexIndex == 2) ? 3.0 : -1.0);
  // Vulkan clip space has y pointing down: y = -1 is the top row. The triangle's far corner lies
  // beyond the screen, so the colour is extrapolated linearly along the same vertical ramp.
  float height = 0.5 - 0.5 * p.y;
  outColor = mix(globals.backgroundBottom.rgb, globals.backgroundTop.rgb, height);
  gl_Position = vec4(p, 1.0, 1.0);
}
