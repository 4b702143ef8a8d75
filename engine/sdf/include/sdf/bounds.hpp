// Conservative axis-aligned bounds of SDF content: the box that holds every point where a
// primitive, a profile solid or a whole SDF subtree has distance <= 0, or the news that the
// content reaches infinity (a plane, an infinite repetition, ...). Used for the proxy boxes of
// mesh-shell objects and for skipping subtrees while ray marching.
//
// The bounds follow what sdf/compiler.hpp compiles and sdf/cpu_eval.hpp evaluates, including
// the places where a node's field is larger than the true distance would be: smooth, chamfer and
// round operations (their blend pushes the surface outwards), distance modifiers (Round, Onion,
// Displace) and fields that are only lower bounds of the distance (non-uniform scale, the step
// corrections of twist, bend and displacement, the non-exact primitives). Internally each part
// of the tree is bounded at a "level" t: the box of every point where its field is <= t.
#pragma once

#include "sdf/primitives.hpp"
#include "sdf/sdf_tree.hpp"

#include <glm/glm.hpp>

#include <limits>
#include <string>

namespace rmsc {

// An axis-aligned box; empty when min > max on some axis (the default).
struct Aabb {
    glm::vec3 min{std::numeric_limits<float>::infinity()};
    glm::vec3 max{-std::numeric_limits<float>::infinity()};

    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    void add(glm::vec3 p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void add(const Aabb& box) {
        if (box.empty()) return;
        min = glm::min(min, box.min);
        max = glm::max(max, box.max);
    }
    glm::vec3 center() const { return 0.5f * (min + max); }
    glm::vec3 halfSize() const { return 0.5f * (max - min); }
    bool contains(glm::vec3 p) const {
        return glm::all(glm::greaterThanEqual(p, min)) && glm::all(glm::lessThanEqual(p, max));
    }
};

// The box [center - half, center + half].
Aabb aabbAround(glm::vec3 center, glm::vec3 half);
// The part of both boxes (empty if they do not overlap).
Aabb intersectAabb(const Aabb& a, const Aabb& b);
// `box` grown by `amount` on every side (an empty box stays empty).
Aabb inflateAabb(const Aabb& box, float amount);
// The box of the 8 corners of `box` through the affine matrix `m` (empty stays empty).
Aabb transformAabb(const Aabb& box, const glm::mat4& m);

struct SdfBounds {
    bool bounded = true;     // false: the content reaches infinity (plane, infinite repetition)
    Aabb box;                // when bounded: holds every point where the distance is <= 0
    std::string unboundedBy; // when unbounded: JSON pointer of the node or modifier responsible
                             // (SdfNode::pointer / SdfModifier::pointer), for messages; "" for
                             // the primitive and profile functions, which know no pointer
};

// The box of a primitive in its local frame. `level` >= 0 asks for every point where the
// primitive's distance function is <= level instead of <= 0 (what a rounding or a smooth union
// of that size reaches); for exact distances it is the level-0 box grown by `level`, for the
// others (ellipsoid, triangular prism, fractals) it is derived from the formula.
SdfBounds primitiveBounds(PrimitiveId id, const PrimitiveParams& params, float level = 0.0f);
// The same for an extruded or revolved 2D profile.
SdfBounds profileBounds(const SdfProfile& profile, float level = 0.0f);

// `parentFieldScale` in the functions below: the field units (world units, in which the
// smoothness of the operations is given) per unit of length of the node's parent frame. 1 for
// the root of a scene's tree; for a subtree, the product of the smallest scale factors of its
// ancestors' transforms divided by their modifiers' step corrections (sdfFieldShrink), or any
// smaller positive number (a smaller value only makes the box larger). A node whose transform
// has a zero scale (which the compiler refuses) is reported unbounded.

// Everything the node draws (its inside: field <= 0) in the node's own local frame: the frame its
// modifiers act in and its children's transforms are relative to (node.transform not applied).
SdfBounds sdfNodeLocalBounds(const SdfNode& node, float parentFieldScale = 1.0f);
// The same in the parent's frame (node.transform applied).
SdfBounds sdfNodeBounds(const SdfNode& node, float parentFieldScale = 1.0f);
// Where the node's field is at most `level` (>= 0, field units), in the parent's frame: every
// point whose field is at most the level lies in the box.
SdfBounds sdfNodeBoundsAtLevel(const SdfNode& node, float level, float parentFieldScale = 1.0f);

} // namespace rmsc
