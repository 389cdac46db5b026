#version 450
// Full-screen triangle for the background gradient; no vertex buffer (three gl_VertexIndex values).
#extension GL_GOOGLE_include_directive : require
#include "shared.h"
#include "common.glsl"

layout(location = 0) out float outHeight;  // 0 at the bottom edge of the image, 1 at the top

void main() {
  vec2 p = vec2((gl_VertexIndex == 1) ? 3.0 : -1.0, (gl_VertexIndex == 2) ? 3.0 : -1.0);
  // Vulkan clip space has y pointing down: y = -1 is the top row.
  outHeight = 0.5 - 0.5 * p.y;
  gl_Position = vec4(p, 1.0, 1.0);
}
