// The quadratic error function of dual contouring: the point that best fits the tangent planes
// (point p_i, unit normal n_i) of the surface where it crosses a cell's edges,
//   E(x) = sum_i (n_i . (x - p_i))^2
// (Ju, Losasso, Schaefer and Warren, "Dual Contouring of Hermite Data", SIGGRAPH 2002, sec. 2.2).
// Solved as they suggest with a truncated pseudo-inverse around the mass point (the mean of the
// p_i): directions in which the planes do not constrain the point (a flat patch, an edge) keep
// the mass point's coordinate, so the point moves only as far as the planes say.
#pragma once

#include <glm/glm.hpp>

namespace rmsc::exporter {

struct Qef {
    glm::dmat3 ata{0.0}; // sum n n^T
    glm::dvec3 atb{0.0}; // sum n (n . p)
    glm::dvec3 sum{0.0}; // sum p
    double btb = 0.0;    // sum (n . p)^2
    int count = 0;

    void add(glm::vec3 point, glm::vec3 normal);
    // The planes of both (the QEF of a cluster of vertices is the sum of theirs).
    Qef& operator+=(const Qef& other);
    // E(x): the sum of squared distances from x to the planes.
    double error(glm::vec3 x) const;
    // The minimizer; eigenvalues of A^T A under `truncation` times the largest are treated as 0.
    // `rank`, when given, gets how many eigenvalues were kept (1: a plane, 2: an edge, 3: a
    // corner).
    glm::vec3 solve(double truncation = 0.01, int* rank = nullptr) const;
    glm::vec3 massPoint() const;
};

} // namespace rmsc::exporter
