#version 330 core
// The room's boxes (floor, walls, table): placed by their entity's transform.
in vec3 vertexPosition;
in vec3 vertexNormal;
uniform mat4 modelMatrix;
uniform mat3 modelNormalMatrix;
uniform mat4 modelViewProjection;
out vec3 worldNormal;
void main() {
    worldNormal = modelNormalMatrix * vertexNormal;
    gl_Position = modelViewProjection * vec4(vertexPosition, 1.0);
}
