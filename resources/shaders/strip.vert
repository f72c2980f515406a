#version 330 core
// Thin strips (ribbons, the drag line) in world coordinates, one colour each entity.
in vec3 vertexPosition;
in vec3 vertexNormal;
uniform mat4 viewProjectionMatrix;
out vec3 worldPosition;
out vec3 worldNormal;
void main() {
    worldPosition = vertexPosition;
    worldNormal = vertexNormal;
    gl_Position = viewProjectionMatrix * vec4(vertexPosition, 1.0);
}
