// Each line of the light-space overview as a screen-space quad u_lineWidth pixels wide: a view
// shown as a thumbnail or on a projector is minified, and one-pixel GL lines then fell between
// the sampled pixels and showed as dots (#26). Core profile contexts have no wide lines.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;
in vec3 v_color[];
out vec3 g_color;
uniform vec2 u_targetSize;  // pixels
uniform float u_lineWidth;  // pixels

void main() {
  vec4 a = gl_in[0].gl_Position, b = gl_in[1].gl_Position;
  // Clip against the near side (w > 0) before the divide, as GL clips a line.
  const float nearW = 1e-4;
  if (a.w < nearW && b.w < nearW) return;
  if (a.w < nearW) a = mix(a, b, (nearW - a.w) / (b.w - a.w));
  if (b.w < nearW) b = mix(b, a, (nearW - b.w) / (a.w - b.w));
  vec2 sa = a.xy / a.w * u_targetSize, sb = b.xy / b.w * u_targetSize;
  vec2 dir = sb - sa;
  float len = length(dir);
  dir = len > 1e-6 ? dir / len : vec2(1.0, 0.0);
  // Half the width on each side, in NDC units (times w, so the divide leaves it in pixels).
  vec2 side = vec2(-dir.y, dir.x) * u_lineWidth / u_targetSize;
  g_color = v_color[0];
  gl_Position = vec4(a.xy + side * a.w, a.zw);
  EmitVertex();
  gl_Position = vec4(a.xy - side * a.w, a.zw);
  EmitVertex();
  g_color = v_color[1];
  gl_Position = vec4(b.xy + side * b.w, b.zw);
  EmitVertex();
  gl_Position = vec4(b.xy - side * b.w, b.zw);
  EmitVertex();
  EndPrimitive();
}
