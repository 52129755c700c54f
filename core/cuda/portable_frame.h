// The host-side bridge from core/triangle_integrals.h to the portable structs the CUDA kernels use: the per-face
// frame is built once on the host by makeTriangleFrame (so both backends share its degeneracy test) and copied.
#pragma once

#include "cuda/triangle_integrals_portable.h"
#include "triangle_integrals.h"

namespace somicage {

inline PortableTriangleFrame portableFrame(const TriangleFrame& f) {
  PortableTriangleFrame p;
  for (int i = 0; i < 3; ++i) {
    p.origin[i] = f.origin[i], p.u[i] = f.u[i], p.v[i] = f.v[i], p.n[i] = f.n[i];
    p.ell[i] = f.ell[i];
    p.ellOverTwiceArea[i] = f.ellOverTwiceArea[i];
    for (int j = 0; j < 2; ++j) p.q[i][j] = f.q[i][j], p.tau[i][j] = f.tau[i][j], p.m[i][j] = f.m[i][j];
    for (int j = 0; j < 2; ++j) p.grad[i][j] = f.grad[i][j];
    for (int j = 0; j < 3; ++j)
      p.mm[i][j] = f.mm[i][j], p.tm[i][j] = f.tm[i][j], p.tt[i][j] = f.tt[i][j], p.mDotGrad[i][j] = f.mDotGrad[i][j];
  }
  p.twiceArea = f.twiceArea;
  p.degenerate = f.degenerate ? 1 : 0;
  return p;
}

}  // namespace somicage
