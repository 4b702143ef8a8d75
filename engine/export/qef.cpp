// The QEF's truncated solve: the eigen-decomposition of the symmetric 3x3 A^T A by cyclic Jacobi
// rotations (Golub and Van Loan, "Matrix Computations", sec. 8.5), which for a symmetric
// positive semi-definite matrix is its singular value decomposition.
#include "qef.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc::exporter {
namespace {

// Diagonalizes the symmetric `a` in place; `v` collects the rotations (columns: eigenvectors).
void jacobi(double a[3][3], double v[3][3]) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            v[i][j] = i == j ? 1.0 : 0.0;
    for (int sweep = 0; sweep < 12; ++sweep) {
        const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        if (off < 1e-24) break;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (std::abs(a[p][q]) < 1e-30) continue;
                const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                const double t =
                    (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0);
                const double s = t * c;
                for (int k = 0; k < 3; ++k) { // a = J^T a J
                    const double akp = a[k][p];
                    const double akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k) {
                    const double apk = a[p][k];
                    const double aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; ++k) {
                    const double vkp = v[k][p];
                    const double vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
    }
}

} // namespace

void Qef::add(glm::vec3 point, glm::vec3 normal) {
    const glm::dvec3 n(normal);
    const glm::dvec3 p(point);
    ata += glm::outerProduct(n, n);
    atb += n * glm::dot(n, p);
    btb += glm::dot(n, p) * glm::dot(n, p);
    sum += p;
    ++count;
}

Qef& Qef::operator+=(const Qef& other) {
    ata += other.ata;
    atb += other.atb;
    sum += other.sum;
    btb += other.btb;
    count += other.count;
    return *this;
}

double Qef::error(glm::vec3 point) const {
    // sum (n . x - n . p)^2 = x^T (sum n n^T) x - 2 x . sum n (n . p) + sum (n . p)^2
    const glm::dvec3 x(point);
    return std::max(0.0, glm::dot(x, ata * x) - 2.0 * glm::dot(x, atb) + btb);
}

glm::vec3 Qef::massPoint() const {
    return count ? glm::vec3(sum / double(count)) : glm::vec3(0.0f);
}

glm::vec3 Qef::solve(double truncation, int* rank) const {
    const glm::dvec3 mass = count ? sum / double(count) : glm::dvec3(0.0);
    double a[3][3];
    double v[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            a[i][j] = ata[j][i]; // glm is column-major: ata[column][row]
    jacobi(a, v);
    const double largest = std::max({std::abs(a[0][0]), std::abs(a[1][1]), std::abs(a[2][2])});
    // x = mass + pinv(A^T A) (A^T b - A^T A mass)
    const glm::dvec3 r = atb - ata * mass;
    glm::dvec3 x = mass;
    if (rank) *rank = 0;
    for (int k = 0; k < 3; ++k) {
        const double lambda = a[k][k];
        if (largest <= 0.0 || std::abs(lambda) <= truncation * largest) continue;
        if (rank) ++*rank;
        const glm::dvec3 e(v[0][k], v[1][k], v[2][k]);
        x += e * (glm::dot(e, r) / lambda);
    }
    return glm::vec3(x);
}

} // namespace rmsc::exporter
