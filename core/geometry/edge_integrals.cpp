#include "geometry/edge_integrals.h"

#include <cmath>
#include <vector>

#include "base/cpu_dispatch.h"
#include "base/dual_eigen.h"

namespace somicage {

// ---------------------------------------------------------------------------------------------------------------
// Closed form.
//
// In the edge frame (tau = e/l, n = (tau_y, -tau_x)) a point of the edge is y = p0 + s tau, s in [0, l]. With
// xi = (x - p0).tau, h = (x - p0).n and u = s - xi in [u0, u1] = [-xi, l - xi]:
//   r = u tau - h n,  R^2 = u^2 + h^2,  n.r = -h,  n_x r_y - n_y r_x = u,  phi_0 = (u1 - u)/l,  phi_1 = (u - u0)/l.
// Every integral is a combination of the moments below. None divides by h, so the supporting line (h = 0) is a
// regular case. Far from the edge (R >> l) the textbook antiderivative differences cancel to O((l/R)^2); the forms
// below avoid that. What remains is the hat weighting (u1 int f - int u f)/l, a difference of terms R/l times the
// result: relative error ~eps R/l, absolute error ~eps, the same order as the conditioning of the integrals with
// respect to the rounding of the edge direction.
// ---------------------------------------------------------------------------------------------------------------
namespace {

void clear(EdgeIntegrals& out) {
  out.S = 0;
  out.M.setZero();
  out.angle = 0;
  for (int k = 0; k < 2; ++k) {
    out.D[k] = out.A[k] = 0;
    out.B[k].setZero();
  }
}

// t - atan(t), accurate for small t (the difference cancels as t^3/3).
template <typename Scalar>
Scalar tMinusAtan(const Scalar& t) {
  using std::abs, std::atan;
  if (abs(t) >= 0.5) return t - atan(t);
  const Scalar q = t * t;
  Scalar power = t * q, sum = 0;
  for (int k = 1; k < 64; ++k) {
    const Scalar term = power / (2 * k + 1);
    sum += (k % 2 == 1) ? term : -term;
    if (abs(term) <= 1e-17 * abs(sum)) break;
    power *= q;
  }
  return sum;
}

// atan(t) - t/(1 + t^2) = sum_{k>=1} (-1)^{k+1} 2k/(2k+1) t^{2k+1}, accurate for small t (cancels as 2t^3/3).
template <typename Scalar>
Scalar atanMinusRational(const Scalar& t) {
  using std::abs, std::atan;
  if (abs(t) >= 0.5) return atan(t) - t / (1 + t * t);
  const Scalar q = t * t;
  Scalar power = t * q, sum = 0;
  for (int k = 1; k < 64; ++k) {
    const Scalar term = power * (2.0 * k) / (2 * k + 1);
    sum += (k % 2 == 1) ? term : -term;
    if (abs(term) <= 1e-17 * abs(sum)) break;
    power *= q;
  }
  return sum;
}

// s = a tt + b tn + c nn for symmetric 2x2 double matrices and Scalar weights.
template <typename Scalar>
void combine(const Scalar& a, const Eigen::Matrix2d& tt, const Scalar& b, const Eigen::Matrix2d& tn, const Scalar& c,
             const Eigen::Matrix2d& nn, Scalar (&s)[2][2]) {
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) s[i][j] = a * tt(i, j) + b * tn(i, j) + c * nn(i, j);
}

// integrateEdgeOf for the point at xi along the edge and h along its normal from p0 (h = -0 on the edge: the limit
// from inside, see integrateEdgeInteriorLimit).
template <typename Scalar>
void integrateEdgeLocalOf(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Scalar& xi, const Scalar& h,
                          EdgeIntegralsOf<Scalar>& out) {
  using std::atan2, std::log, std::log1p;
  const Eigen::Vector2d e = p1 - p0;
  const double l = e.norm();
  out.S = out.angle = 0;
  for (int k = 0; k < 2; ++k) {
    out.D[k] = out.A[k] = 0;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) out.M[i][j] = out.B[k][i][j] = 0;
  }
  if (l == 0) return;  // a zero-length edge carries no boundary

  const Eigen::Vector2d tau = e / l, n(tau.y(), -tau.x());
  const Scalar u0 = -xi, u1 = l - xi;
  const Scalar hh = h * h, u01 = u0 * u1;
  const Scalar R0sq = u0 * u0 + hh, R1sq = u1 * u1 + hh;

  // theta = h int du/R^2, the signed angle subtended (one atan2: exact for both signs of h and for h = 0).
  // With c = h^2 + u0 u1 and y = h l: theta = atan2(y, c), and R0^2 R1^2 = c^2 + y^2 exactly.
  const Scalar c = hh + u01, y = h * l;
  const Scalar theta = atan2(y, c);
  const Scalar P = R0sq * R1sq;

  // L = int u/R^2 = ln(R1/R0), from the larger of the two radii so that log1p's argument is >= 0
  // (R1^2 - R0^2 = l (u0 + u1) has no cancellation).
  const Scalar sumU = u0 + u1;
  const bool farEnd1 = R1sq >= R0sq;
  const Scalar L = farEnd1 ? 0.5 * log1p(l * sumU / R0sq) : -0.5 * log1p(-l * sumU / R1sq);

  // I2 = int u^2/R^2 = l - h theta;   W0 = h^3 int du/R^4 = (theta + h [u/R^2])/2;
  // V2 = h int u^2/R^4 = (theta - h [u/R^2])/2, with h [u/R^2]_{u0}^{u1} = y (h^2 - u0 u1)/P.
  // Away from the edge (c > 0, |y| <= c, so t = y/c = tan(theta)) each of them is a difference of O(1) terms
  // that cancel to O(t^2): rewritten with t - atan t and atan t - t/(1+t^2), the remaining terms share a sign
  // (W0, and I2 / V2 when u0 u1 >= 0) or cancel by at most a small constant factor (u0 u1 < 0 needs h^2 > |u0 u1|).
  Scalar I2, W0, V2;
  if (c > 0 && valueOf(y) <= valueOf(c) && -valueOf(y) <= valueOf(c)) {
    const Scalar t = y / c;
    const Scalar g = atanMinusRational(t);
    I2 = h * tMinusAtan(t) + u01 * l / c;
    W0 = 0.5 * (g + 2 * hh * y / P);
    V2 = 0.5 * (g + 2 * u01 * y / P);
  } else {
    // Near the edge: theta is O(1) and the terms do not cancel.
    const Scalar hBracket = y * (hh - u01) / P;
    I2 = l - h * theta;
    W0 = 0.5 * (theta + hBracket);
    V2 = 0.5 * (theta - hBracket);
  }
  // E1 = int u/R^4 = (1/R0^2 - 1/R1^2)/2, written without the difference.
  const Scalar E1 = 0.5 * l * sumU / P;
  // V3 = h int u^3/R^4 = h (L - h^2 E1).
  const Scalar V3 = h * (L - hh * E1);

  // S = int ln(1/R) = -1/2 int ln(u^2 + h^2) = l - h theta - [u ln R]_{u0}^{u1} = I2 - Lambda. Lambda is split
  // around the farther endpoint: the remaining u_near * L tends to 0 (0 log 0 := 0) as x approaches the near end,
  // and is O(l) far away, where u1 ln R1 - u0 ln R0 would cancel.
  Scalar Lambda;
  if (farEnd1) {
    Lambda = 0.5 * l * log(R1sq) + (u0 == 0 ? Scalar(0.0) : u0 * L);
  } else {
    Lambda = 0.5 * l * log(R0sq) + (u1 == 0 ? Scalar(0.0) : u1 * L);
  }
  out.S = I2 - Lambda;

  // Edge-frame tensors.
  const Eigen::Matrix2d tt = tau * tau.transpose();
  const Eigen::Matrix2d tn = tau * n.transpose() + n * tau.transpose();
  const Eigen::Matrix2d nn = n * n.transpose();

  // M = int r r^T/R^2 = tt int u^2/R^2 - tn h int u/R^2 + nn h^2 int 1/R^2.
  combine<Scalar>(I2, tt, -(h * L), tn, h * theta, nn, out.M);
  out.angle = theta;

  // Hat-weighted moments: int phi_0 f = (u1 int f - int u f)/l, int phi_1 f = (int u f - u0 int f)/l.
  const double invL = 1.0 / l;
  // D_k = -h int phi_k / R^2: int -h/R^2 = -theta, int -h u/R^2 = -h L.
  out.D[0] = (h * L - u1 * theta) * invL;
  out.D[1] = (u0 * theta - h * L) * invL;
  // A_k = int phi_k u/R^2.
  out.A[0] = (u1 * L - I2) * invL;
  out.A[1] = (I2 - u0 * L) * invL;
  // B_k = int phi_k (-h)(u^2 tt - u h tn + h^2 nn)/R^4
  //     = -(h int phi_k u^2/R^4) tt + (h^2 int phi_k u/R^4) tn - (h^3 int phi_k/R^4) nn.
  const Scalar hhE1 = hh * E1, hV2 = h * V2, h3E1 = h * hhE1;
  const Scalar btt0 = -(u1 * V2 - V3) * invL, btt1 = -(V3 - u0 * V2) * invL;
  const Scalar btn0 = (u1 * hhE1 - hV2) * invL, btn1 = (hV2 - u0 * hhE1) * invL;
  const Scalar bnn0 = -(u1 * W0 - h3E1) * invL, bnn1 = -(h3E1 - u0 * W0) * invL;
  combine<Scalar>(btt0, tt, btn0, tn, bnn0, nn, out.B[0]);
  combine<Scalar>(btt1, tt, btn1, tn, bnn1, nn, out.B[1]);
}

void toEigen(const EdgeIntegralsOf<double>& I, EdgeIntegrals& out) {
  out.S = I.S;
  out.angle = I.angle;
  out.M = Eigen::Map<const Eigen::Matrix<double, 2, 2, Eigen::RowMajor>>(&I.M[0][0]);
  for (int k = 0; k < 2; ++k) {
    out.D[k] = I.D[k];
    out.A[k] = I.A[k];
    out.B[k] = Eigen::Map<const Eigen::Matrix<double, 2, 2, Eigen::RowMajor>>(&I.B[k][0][0]);
  }
}

}  // namespace

namespace {

template <typename Scalar>
void integrateEdgePoint(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Scalar x[2],
                        EdgeIntegralsOf<Scalar>& out) {
  const Eigen::Vector2d e = p1 - p0;
  const double l = e.norm();
  if (l == 0) return integrateEdgeLocalOf<Scalar>(p0, p1, Scalar(0), Scalar(0), out);
  const Eigen::Vector2d tau = e / l, n(tau.y(), -tau.x());
  // Eigen's dot, as before the scalar became a template: a contracted a*b + c*d would give points on the
  // supporting line a rounding-sized h instead of 0.
  const Eigen::Matrix<Scalar, 2, 1> d(x[0] - p0.x(), x[1] - p0.y());
  integrateEdgeLocalOf<Scalar>(p0, p1, d.dot(tau), d.dot(n), out);
}

}  // namespace

// The 2D kernels, dispatched (cpu_dispatch.h): each call is one point and one edge.
SOMICAGE_DISPATCH void integrateEdgeOf(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const double x[2],
                                       EdgeIntegralsOf<double>& out) {
  integrateEdgePoint(p0, p1, x, out);
}

SOMICAGE_DISPATCH void integrateEdgeOf(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const dual::Dual<2> x[2],
                                       EdgeIntegralsOf<dual::Dual<2>>& out) {
  integrateEdgePoint(p0, p1, x, out);
}

void integrateEdge(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& x, EdgeIntegrals& out) {
  EdgeIntegralsOf<double> I;
  const double point[2] = {x.x(), x.y()};
  integrateEdgeOf(p0, p1, point, I);
  toEigen(I, out);
}

SOMICAGE_DISPATCH void integrateEdgeInteriorLimit(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1,
                                                  const Eigen::Vector2d& onEdge, EdgeIntegrals& out) {
  const Eigen::Vector2d e = p1 - p0;
  const double l = e.norm();
  EdgeIntegralsOf<double> I;
  integrateEdgeLocalOf<double>(p0, p1, l == 0 ? 0 : (onEdge - p0).dot(e) / l, -0.0, I);
  toEigen(I, out);
}

// ---------------------------------------------------------------------------------------------------------------
// Composite Gauss-Legendre quadrature.
// ---------------------------------------------------------------------------------------------------------------
namespace {

struct GaussRule {
  int n = 0;
  std::vector<double> nodes, weights;  // on [-1, 1]
};

// Roots of P_n by Newton's method from the usual guess cos(pi (i - 1/4)/(n + 1/2)), i = 1..n; weights
// 2 / ((1 - x^2) P_n'(x)^2). The rule is cached per thread, so concurrent callers need no lock.
const GaussRule& gaussLegendre(int n) {
  thread_local GaussRule rule;
  if (rule.n == n) return rule;
  rule.n = n;
  rule.nodes.assign(n, 0.0);
  rule.weights.assign(n, 0.0);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 1;
    for (int iter = 0; iter < 100; ++iter) {
      double pPrev = 1, p = z;  // P_0, P_1
      for (int k = 2; k <= n; ++k) {
        const double pNext = ((2 * k - 1) * z * p - (k - 1) * pPrev) / k;
        pPrev = p;
        p = pNext;
      }
      dp = n * (z * p - pPrev) / (z * z - 1);  // P_n'(z)
      const double step = p / dp;
      z -= step;
      if (std::abs(step) <= 1e-15) break;
    }
    // One more derivative at the converged root for the weight.
    double pPrev = 1, p = z;
    for (int k = 2; k <= n; ++k) {
      const double pNext = ((2 * k - 1) * z * p - (k - 1) * pPrev) / k;
      pPrev = p;
      p = pNext;
    }
    dp = n * (z * p - pPrev) / (z * z - 1);
    const double w = 2 / ((1 - z * z) * dp * dp);
    rule.nodes[i] = -z;
    rule.nodes[n - 1 - i] = z;
    rule.weights[i] = rule.weights[n - 1 - i] = w;
  }
  if (n % 2 == 1) rule.nodes[n / 2] = 0;  // exact centre node
  return rule;
}

}  // namespace

void integrateEdgeGauss(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& x, int segments,
                        int pointsPerSegment, EdgeIntegrals& out) {
  clear(out);
  const Eigen::Vector2d e = p1 - p0;
  const double l = e.norm();
  if (l == 0 || segments < 1 || pointsPerSegment < 1) return;

  const GaussRule& rule = gaussLegendre(pointsPerSegment);
  const Eigen::Vector2d tau = e / l, n(tau.y(), -tau.x()), d = x - p0;
  // r = y - x is formed in the edge frame (r = (s - xi) tau - h n) rather than as p0 + s tau - x, so that points
  // very close to the edge do not lose the digits of h to the cancellation of two nearby positions. The two
  // projections are taken exactly, n.r = -h and n_x r_y - n_y r_x = n x r = s - xi: formed from the rounded r they
  // would be buried under eps |r| where they are small (near the supporting line, far along the normal).
  const double xi = d.dot(tau), h = d.dot(n);
  const double segLen = l / segments;
  for (int seg = 0; seg < segments; ++seg) {
    const double s0 = seg * segLen;
    for (int q = 0; q < pointsPerSegment; ++q) {
      const double s = s0 + 0.5 * segLen * (1 + rule.nodes[q]);
      const double w = 0.5 * segLen * rule.weights[q];
      const double u = s - xi;
      const Eigen::Vector2d r = u * tau - h * n;
      const double R2 = r.squaredNorm(), nr = -h, cross = u;
      const double phi[2] = {1 - s / l, s / l};
      out.S += w * (-0.5 * std::log(R2));
      out.M += (w / R2) * r * r.transpose();
      out.angle += w * h / R2;
      for (int k = 0; k < 2; ++k) {
        const double wk = w * phi[k];
        out.D[k] += wk * nr / R2;
        out.A[k] += wk * cross / R2;
        out.B[k] += (wk * nr / (R2 * R2)) * r * r.transpose();
      }
    }
  }
}

}  // namespace somicage
