#version 450
// Shaded faces: a headlight (from the eye) plus a key light fixed to the camera, hemisphere
// ambient and a faint specular. Normals are the exact surface normals, interpolated.
#extension GL_GOOGLE_include_directive : require
#include "shared.h"
#include "common.glsl"

layout(location = 0) in vec3 inViewPosition;
layout(location = 1) in vec3 inViewNormal;
layout(location = 2) flat in vec4 inColor;

layout(location = 0) out vec4 outColor;

void main() {
  vec3 n = normalize(inViewNormal);
  bool ortho = (globals.flags.x & CETVIEW_FLAG_ORTHOGRAPHIC) != 0u;
  vec3 toEye = ortho ? vec3(0.0, 0.0, 1.0) : normalize(-inViewPosition);
  // Two-sided: open shells and faces seen from behind are lit like their front.
  if (dot(n, toEye) < 0.0) n = -n;

  vec3 toKey = globals.keyLightDir.xyz;
  float headlight = max(dot(n, toEye), 0.0);
  float key = max(dot(n, toKey), 0.0);
  // Hemisphere ambient: surfaces facing up (view space) get a little more sky.
  float sky = mix(0.55, 1.0, 0.5 + 0.5 * n.y);
  vec3 halfway = normalize(toKey + toEye);
  float specular = pow(max(dot(n, halfway), 0.0), 48.0);

  vec4 k = globals.lightIntensity;
  vec3 lit = inColor.rgb * (k.x * headlight + k.y * key + k.z * sky) + vec3(k.w * specular);
  outColor = toTarget(lit);
}
