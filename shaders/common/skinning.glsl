// Skinning on the GPU (glTF 2.0 section 3.7.3, "Skins"): a vertex moved by the weighted sum of
// its joints' matrices, world(joint) * inverseBindMatrix, read from the mesh's joint-matrix
// buffer (MeshAsset::jointMatrices). Mirrors skinVertices in engine/scene/mesh_pose.cpp.
#include "generated/constants.glsl"

layout(std430, binding = JOINT_MATRIX_BINDING) readonly buffer JointMatrixBlock {
    mat4 jointMatrices[]; // per skinned node: its world matrix, then one per joint
};

layout(location = 6) in uvec4 inJoints0;
layout(location = 7) in uvec4 inJoints1;
layout(location = 8) in vec4 inWeights0;
layout(location = 9) in vec4 inWeights1;

// Where the primitive's node's matrices start in jointMatrices; -1 for a primitive not skinned.
uniform int uJointBase;

bool skinned() { return uJointBase >= 0; }

// The blended matrix of this vertex; the node's own world matrix when its weights are all zero.
mat4 skinMatrix() {
    mat4 m = mat4(0.0);
    float total = 0.0;
    for (int c = 0; c < 4; ++c)
        if (inWeights0[c] != 0.0) {
            m += inWeights0[c] * jointMatrices[uJointBase + 1 + int(inJoints0[c])];
            total += inWeights0[c];
        }
    for (int c = 0; c < 4; ++c)
        if (inWeights1[c] != 0.0) {
            m += inWeights1[c] * jointMatrices[uJointBase + 1 + int(inJoints1[c])];
            total += inWeights1[c];
        }
    return total > 0.0 ? m : jointMatrices[uJointBase];
}

// Normals are moved by the inverse transpose of the blended matrix (the matrix itself when it
// is singular), as on the CPU.
mat3 skinNormalMatrix(mat4 m) {
    mat3 linear = mat3(m);
    return abs(determinant(linear)) > 1e-30 ? transpose(inverse(linear)) : linear;
}
