#version 450
// Faces: one indirect draw per face, firstInstance = face id, so gl_InstanceIndex names the face.
#extension GL_GOOGLE_include_directive : require
#include "shared.h"
#include "common.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;

layout(location = 0) out vec3 outViewPosition;
layout(location = 1) out vec3 outViewNormal;
layout(location = 2) flat out vec4 outColor;

void main() {
  mat4 model = instances[draw.instance].model;
  vec4 world = model * vec4(inPosition, 1.0);
  gl_Position = globals.viewProj * world;
  outViewPosition = (globals.view * world).xyz;
  outViewNormal = mat3(globals.view) * (mat3(instances[draw.instance].normalMatrix) * inNormal);

  vec4 color = globals.defaultFaceColor;
  if ((globals.flags.x & CETVIEW_FLAG_FILE_COLORS) != 0u) {
    if ((instances[draw.instance].flags.x & CETVIEW_INSTANCE_COLOR_OVERRIDE) != 0u) {
      color = instances[draw.instance].color;
    } else {
      vec4 packed = unpackUnorm4x8(faceColors[gl_InstanceIndex]);
      color = vec4(srgbToLinear(packed.rgb), packed.a);
    }
  }
  outColor = color;
}
