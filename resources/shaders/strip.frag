#version 330 core
// Both sides lit alike: a strip's normal may face either way.
in vec3 worldPosition;
in vec3 worldNormal;
uniform vec3 eyePosition;
uniform vec4 stripColor;
uniform float unlit;  // 1: flat colour (the drag line)
out vec4 fragColor;
void main() {
    vec3 n = normalize(worldNormal);
    vec3 v = normalize(eyePosition - worldPosition);
    if (dot(n, v) < 0.0) n = -n;
    vec3 keyDir = normalize(vec3(0.35, 0.8, 0.6));
    float light = 0.45 + 0.55 * max(dot(n, keyDir), 0.0);
    fragColor = vec4(mix(stripColor.rgb * light, stripColor.rgb, unlit), 1.0);
}
