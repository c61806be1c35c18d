// Two-component vectors and 2x2 matrices for the bidirectional (plan) laws: a horizontal
// deformation u = (u_x, u_y), a force, and their tangents. Plain values with no alignment rules,
// so they sit in state arrays and variants as they are, and nothing here allocates.
#pragma once

#include <cmath>

namespace isolab::hysteresis {

struct Vec2 {
  double x = 0.0, y = 0.0;
  bool operator==(const Vec2&) const = default;
};

inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
inline Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
inline Vec2 operator/(Vec2 a, double s) { return {a.x / s, a.y / s}; }
inline double Dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double Norm(Vec2 a) { return std::sqrt(a.x * a.x + a.y * a.y); }
// a rotated by +90 degrees.
inline Vec2 Perpendicular(Vec2 a) { return {-a.y, a.x}; }

// Row-major [xx xy; yx yy].
struct Mat2 {
  double xx = 0.0, xy = 0.0, yx = 0.0, yy = 0.0;
};

inline Mat2 operator+(const Mat2& a, const Mat2& b) {
  return {a.xx + b.xx, a.xy + b.xy, a.yx + b.yx, a.yy + b.yy};
}
inline Mat2 operator-(const Mat2& a, const Mat2& b) {
  return {a.xx - b.xx, a.xy - b.xy, a.yx - b.yx, a.yy - b.yy};
}
inline Mat2 operator-(const Mat2& a) { return {-a.xx, -a.xy, -a.yx, -a.yy}; }
inline Mat2 operator*(double s, const Mat2& a) { return {s * a.xx, s * a.xy, s * a.yx, s * a.yy}; }
inline Vec2 operator*(const Mat2& a, Vec2 b) {
  return {a.xx * b.x + a.xy * b.y, a.yx * b.x + a.yy * b.y};
}
inline Mat2 operator*(const Mat2& a, const Mat2& b) {
  return {a.xx * b.xx + a.xy * b.yx, a.xx * b.xy + a.xy * b.yy, a.yx * b.xx + a.yy * b.yx,
          a.yx * b.xy + a.yy * b.yy};
}
inline Mat2 Identity(double s = 1.0) { return {s, 0.0, 0.0, s}; }
// a b^T.
inline Mat2 Outer(Vec2 a, Vec2 b) { return {a.x * b.x, a.x * b.y, a.y * b.x, a.y * b.y}; }
// I - n n^T for a unit n: the projection onto the direction normal to n.
inline Mat2 NormalProjector(Vec2 n) { return Identity() - Outer(n, n); }
inline Mat2 Transpose(const Mat2& a) { return {a.xx, a.yx, a.xy, a.yy}; }
inline double Determinant(const Mat2& a) { return a.xx * a.yy - a.xy * a.yx; }
inline Mat2 Inverse(const Mat2& a) {
  const double d = Determinant(a);
  return {a.yy / d, -a.xy / d, -a.yx / d, a.xx / d};
}
// x with a x = b.
inline Vec2 Solve(const Mat2& a, Vec2 b) {
  const double d = Determinant(a);
  return {(a.yy * b.x - a.xy * b.y) / d, (a.xx * b.y - a.yx * b.x) / d};
}

}  // namespace isolab::hysteresis
