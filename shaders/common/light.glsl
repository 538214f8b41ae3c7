uniform vec3 u_lightDirection;  // direction light travels
uniform vec3 u_lightPosition;
uniform float u_lightIsSpot;
uniform float u_spotCosHalfAngle;

vec3 directionToLight(vec3 p) {
  return u_lightIsSpot > 0.5 ? normalize(u_lightPosition - p) : -normalize(u_lightDirection);
}

// 0 outside a spot light's cone (the reference treats those points as unlit too).
float spotFactor(vec3 p) {
  if (u_lightIsSpot < 0.5) return 1.0;
  return dot(normalize(p - u_lightPosition), normalize(u_lightDirection)) >= u_spotCosHalfAngle ? 1.0 : 0.0;
}
