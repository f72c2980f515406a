#version 330 core
// Wood-like blocks: soft key and fill light, a faint grain along the block
// and darkened edges so neighbouring blocks of one colour stay distinct.
in vec3 worldPosition;
in vec3 worldNormal;
in vec3 localPosition;
in vec3 halfSize;
in vec3 localNormal;
in vec3 baseColor;
in float highlight;

uniform vec3 eyePosition;

out vec4 fragColor;

void main() {
    vec3 n = normalize(worldNormal);
    vec3 v = normalize(eyePosition - worldPosition);
    vec3 keyDir = normalize(vec3(0.35, 0.8, 0.6));
    vec3 fillDir = normalize(vec3(-0.6, 0.2, 0.4));
    float key = max(dot(n, keyDir), 0.0);
    float fill = max(dot(n, fillDir), 0.0);
    float sky = 0.5 + 0.5 * n.y;
    vec3 h = normalize(keyDir + v);
    float spec = pow(max(dot(n, h), 0.0), 40.0) * 0.12;

    // Distance to the nearest edge of the face being drawn, in metres.
    vec3 d = halfSize - abs(localPosition);
    float edge = min(min(d.x + (abs(localNormal.x) > 0.5 ? 1.0 : 0.0), d.y + (abs(localNormal.y) > 0.5 ? 1.0 : 0.0)),
                     d.z + (abs(localNormal.z) > 0.5 ? 1.0 : 0.0));
    float outline = smoothstep(0.0, 0.0012, edge);
    float grain = 0.94 + 0.06 * sin(localPosition.y * 900.0 + sin(localPosition.x * 300.0) * 2.0);

    vec3 color = baseColor * grain;
    color = mix(color, vec3(1.0, 0.55, 0.2), 0.45 * highlight);
    vec3 lit = color * (0.28 + 0.17 * sky + 0.62 * key + 0.18 * fill) + vec3(spec);
    lit *= mix(0.55, 1.0, outline);
    fragColor = vec4(lit, 1.0);
}
