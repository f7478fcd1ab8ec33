#include "tessellate/predicates.hpp"

#include <cmath>
#include <limits>

namespace curvetext::detail {
namespace {

// Error-free transformations (Knuth two-sum, fma two-product): a + b == s + e
// and a * b == p + e exactly, for finite doubles without overflow/underflow.
inline void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bv = s - a;
  const double av = s - bv;
  e = (a - av) + (b - bv);
}
inline void two_product(double a, double b, double& p, double& e) {
  p = a * b;
  e = std::fma(a, b, -p);
}

}  // namespace

int exact_sign_of_sum(const double* terms, int count) {
  // Shewchuk's Grow-Expansion: adding each term to a non-overlapping expansion
  // keeps it exact and non-overlapping with components in increasing magnitude,
  // so the sign of the sum is the sign of the largest non-zero component.
  double expansion[64];
  int size = 0;
  for (int i = 0; i < count; ++i) {
    double q = terms[i];
    int out = 0;
    for (int j = 0; j < size; ++j) {
      double s, e;
      two_sum(q, expansion[j], s, e);
      q = s;
      if (e != 0.0) expansion[out++] = e;  // zero elimination keeps it short
    }
    if (q != 0.0) expansion[out++] = q;
    size = out;
  }
  for (int j = size - 1; j >= 0; --j) {
    if (expansion[j] > 0.0) return 1;
    if (expansion[j] < 0.0) return -1;
  }
  return 0;
}

int orient2d_exact(Vec2 a, Vec2 b, Vec2 c) {
  // Stage B, for the common undecided case of font coordinates (small
  // integers or short binary fractions, often exactly collinear): when the
  // four differences and both products are exact (their error terms are
  // zero), det = fl(detleft - detright) has the exact sign, because one
  // correctly rounded subtraction keeps the sign and is zero only for equal
  // operands.
  double acx, acx_e, bcy, bcy_e, acy, acy_e, bcx, bcx_e;
  two_sum(a.x, -c.x, acx, acx_e);
  two_sum(b.y, -c.y, bcy, bcy_e);
  two_sum(a.y, -c.y, acy, acy_e);
  two_sum(b.x, -c.x, bcx, bcx_e);
  if (acx_e == 0.0 && bcy_e == 0.0 && acy_e == 0.0 && bcx_e == 0.0) {
    double l, l_e, r, r_e;
    two_product(acx, bcy, l, l_e);
    two_product(acy, bcx, r, r_e);
    if (l_e == 0.0 && r_e == 0.0) {
      const double det = l - r;
      return det > 0.0 ? 1 : det < 0.0 ? -1 : 0;
    }
  }

  // Slow path: each difference is split exactly into value + rounding error,
  // the products expanded into 16 exact terms, and their sum's sign found
  // exactly.
  const double left[2] = {acx, acx_e};
  const double left2[2] = {bcy, bcy_e};
  const double right[2] = {acy, acy_e};
  const double right2[2] = {bcx, bcx_e};
  double terms[16];
  int n = 0;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      double p, e;
      two_product(left[i], left2[j], p, e);
      terms[n++] = p;
      terms[n++] = e;
      two_product(right[i], right2[j], p, e);
      terms[n++] = -p;
      terms[n++] = -e;
    }
  }
  return exact_sign_of_sum(terms, n);
}

long double incircle(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const long double adx = (long double)a.x - d.x, ady = (long double)a.y - d.y;
  const long double bdx = (long double)b.x - d.x, bdy = (long double)b.y - d.y;
  const long double cdx = (long double)c.x - d.x, cdy = (long double)c.y - d.y;
  const long double alift = adx * adx + ady * ady;
  const long double blift = bdx * bdx + bdy * bdy;
  const long double clift = cdx * cdx + cdy * cdy;
  return alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) + clift * (adx * bdy - bdx * ady);
}

}  // namespace curvetext::detail
