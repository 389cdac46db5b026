#version 450
// Shaded faces: a headlight (along the view axis) plus a key light fixed to the camera, hemisphere
// ambient and a faint specular, with the exact surface normals interpolated. In view space, where
// every light vector is a constant (shared.h), so all of it folds into a few multiply-adds.
#extension GL_GOOGLE_include_directive : require
#include "shared.h"
#include "common.glsl"

layout(location = 0) in vec3 inNormal;  // view space
#ifndef CETVIEW_COLOR_PUSHED
layout(location = 1) flat in vec3 inColor;
#endif

layout(location = 0) out vec4 outColor;

const vec3 kKeyLight = vec3(CETVIEW_KEY_LIGHT_X, CETVIEW_KEY_LIGHT_Y, CETVIEW_KEY_LIGHT_Z);
// Blinn-Phong half vector of the key light and the eye (at infinity, along +z).
const vec3 kHalfway = normalize(kKeyLight + vec3(0.0, 0.0, 1.0));

void main() {
  vec3 n = normalize(inNormal);
  // Two-sided: open shells and faces seen from behind are lit like their front.
  if (kTwoSided && n.z < 0.0) n = -n;
  float facing = max(n.z, 0.0);  // the headlight, towards the eye
  float key = max(dot(n, kKeyLight), 0.0);
  // Hemisphere ambient: surfaces facing screen-up get a little more sky.
  float sky = 0.775 + 0.225 * n.y;
  // Blinn-Phong with exponent 32 by repeated squaring (pow is costly on software rasterisers).
  float s = max(dot(n, kHalfway), 0.0);
  s *= s;
  s *= s;
  s *= s;
  s *= s;
  s *= s;

#ifdef CETVIEW_COLOR_PUSHED
  vec3 color = draw.color.rgb;  // the run's colour (mesh.vert)
#else
  vec3 color = inColor;
#endif
  vec3 lit = color * (CETVIEW_LIGHT_HEADLIGHT * facing + CETVIEW_LIGHT_KEY * key + CETVIEW_LIGHT_SKY * sky) +
             vec3(CETVIEW_LIGHT_SPECULAR * s);
  outColor = toTarget(lit);
}
