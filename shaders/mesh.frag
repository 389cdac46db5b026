#version 450
// Shaded faces: a headlight (along the view axis) plus a key light fixed to the camera, hemisphere
// ambient and a faint specular, with the exact surface normals interpolated. All in part space.
#extension GL_GOOGLE_include_directive : require
#include "shared.h"
#include "common.glsl"

layout(location = 0) in vec3 inNormal;
layout(location = 1) flat in vec3 inColor;

layout(location = 0) out vec4 outColor;

void main() {
  vec3 n = normalize(inNormal);
  vec3 toEye = draw.toEye.xyz;
  float facing = dot(n, toEye);
  // Two-sided: open shells and faces seen from behind are lit like their front.
  if (draw.toEye.w > 0.5 && facing < 0.0) {
    n = -n;
    facing = -facing;
  }
  facing = max(facing, 0.0);
  vec3 toKey = draw.keyLight.xyz;
  float key = max(dot(n, toKey), 0.0);
  // Hemisphere ambient: surfaces facing screen-up get a little more sky.
  float sky = 0.775 + 0.225 * dot(n, draw.up.xyz);
  // Blinn-Phong with exponent 32 by repeated squaring (pow is costly on software rasterisers).
  float s = max(dot(n, normalize(toKey + toEye)), 0.0);
  s *= s;
  s *= s;
  s *= s;
  s *= s;
  s *= s;

  vec4 k = globals.lightIntensity;
  vec3 color = kColorPushed ? draw.color.rgb : inColor;
  vec3 lit = color * (k.x * facing + k.y * key + k.z * sky) + vec3(k.w * s);
  outColor = toTarget(lit);
}
