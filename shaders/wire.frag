#version 450
// Wireframe of the triangle edges (polygon mode LINE): the face colour, a little darker so thin
// lines stay readable on the light background. Built twice, as mesh.vert is: with
// CETVIEW_COLOR_PUSHED (wire_pushed_frag) the colour is the draw's, otherwise the face's varying.
#extension GL_GOOGLE_include_directive : require
#include "shared.h"
#include "common.glsl"

layout(location = 0) in vec3 inNormal;  // unused; declared so the interface matches mesh.vert
#ifndef CETVIEW_COLOR_PUSHED
layout(location = 1) flat in vec3 inColor;
#endif

layout(location = 0) out vec4 outColor;

void main() {
#ifdef CETVIEW_COLOR_PUSHED
  vec3 color = draw.color.rgb;
#else
  vec3 color = inColor;
#endif
  outColor = toTarget(color * 0.6);
}
