#version 330 core
// Matte surfaces under a high window and a lamp, both far off: a colour
// per box and two fixed directions. It covers most of the view, so it
// stays cheap (the software renderer shades every pixel on the processor;
// Qt3D's own lit materials cost more than all of a long ladder's blocks).
in vec3 worldNormal;
uniform vec4 surfaceColor;
out vec4 fragColor;
void main() {
    vec3 n = normalize(worldNormal);
    vec3 sun = normalize(vec3(0.35, 0.8, 0.6));
    vec3 lamp = normalize(vec3(1.0, 2.0, 2.0));
    float light = 0.33 + 0.6 * max(dot(n, sun), 0.0) + 0.35 * max(dot(n, lamp), 0.0);
    fragColor = vec4(surfaceColor.rgb * light, 1.0);
}
