#version 430 core
// One frame of core/deform/frame_evaluation.h on the GPU (render/gpu_deformer.cpp):
//
//   y_p   = C_p,main . W_main  (into the outputs from MAIN_OFFSET on)  +  C_p,tail . W_tail
//   out_p = y_p                                  when FINISH == 0 (FrameFinish::Linear: Green, mean value, ...)
//   out_p = T_p^-1 b_p, T_p = y_p[0 : DIM^2] row-major, b_p = y_p[DIM^2 :]   when FINISH == 1 (SolveT: Eq. 11)
//
// Compile-time constants, defined by render/gpu_deformer.cpp right after the #version line:
//   DIM (2 or 3), FINISH (core/deform/frame_finish.h: 0 Linear, 1 SolveT), OUTPUTS (DIM or DIM*DIM+DIM, FINISH's),
//   MAIN_OFFSET (first output that W_main feeds),
//   ROW_THREADS (invocations sharing one point: they read its row of C side by side, coalesced, and reduce in
//   shared memory; 1 = one invocation per point), GROUP_POINTS (points per work group), SPARSE (1: C is stored as
//   sparse rows of uRowEntries (value, column) pairs, core/deform/coordinate_layout.h; 0: dense rows).
// Rows from uMeshPoints on are the exterior points' proxy and anchor rows (core/deform/frame_evaluation.h): they go to
// the Extra buffer, which shaders/exterior_blend.comp.glsl then folds into the positions.
// Storage is float throughout (C converted once at upload, W every frame): the error budget is in
// render/gpu_deformer.h.

#define MAIN_OUTPUTS (OUTPUTS - MAIN_OFFSET)

layout(local_size_x = ROW_THREADS, local_size_y = GROUP_POINTS) in;

// The rows [uFirstPoint, uFirstPoint + uNumPoints) of C (#P by uMainColumns + uTailColumns, row-major).
layout(std430, binding = 0) readonly buffer Coordinates { float C[]; };
// SPARSE: these rows hold uRowEntries values each, and EntryColumns their columns of C in the same places.
#if SPARSE
layout(std430, binding = 4) readonly buffer EntryColumns { uint entryColumns[]; };
uniform uint uRowEntries;
#endif
// W_main (uMainColumns by MAIN_OUTPUTS, row-major), then W_tail (uTailColumns by OUTPUTS, row-major).
layout(std430, binding = 1) readonly buffer Weights { float W[]; };
// The mesh renderer's vertex buffer: #P by 3 floats (z = 0 in 2D).
layout(std430, binding = 2) writeonly buffer Positions { float positions[]; };
// The proxy and anchor rows: 2 #E by 3 floats.
layout(std430, binding = 3) writeonly buffer Extra { float extra[]; };

uniform uint uMeshPoints;  // #P: rows of C from here on are exterior rows
uniform uint uNumPoints;
uniform uint uFirstPoint;
uniform uint uMainColumns;
uniform uint uTailColumns;
uniform vec3 uOrigin;  // FrameWeights::origin: the solve returns uOrigin + T^-1 b
// kSingularT of core/deform/frame_point_kernel.h for float sums: below it det T is rounding noise in float.
const float SINGULAR_T = 1e-6;

#if ROW_THREADS > 1
shared float partial[GROUP_POINTS][OUTPUTS][ROW_THREADS];
#endif

vec3 finish(float y[OUTPUTS]) {
#if FINISH == 0
#if DIM == 3
  return vec3(y[0], y[1], y[2]);
#else
  return vec3(y[0], y[1], 0.0);
#endif
#elif DIM == 3
  // T = S + A (core/deform/frame_evaluation.h): S = (xx, yy, zz, xy, xz, yz) = y[0..5], A w = omega x w, omega =
  // y[6..8]. mat3(...) fills columns, so the rows below are written as columns and transposed; solve T x = b.
  const mat3 T = transpose(mat3(y[0], y[3] - y[8], y[4] + y[7],
                                y[3] + y[8], y[1], y[5] - y[6],
                                y[4] - y[7], y[5] + y[6], y[2]));
  const vec3 b = vec3(y[9], y[10], y[11]);
  const float norm2 = dot(T[0], T[0]) + dot(T[1], T[1]) + dot(T[2], T[2]);
  // Singular T (core/deform/frame_point_kernel.h): the regularised least-squares solution instead.
  if (abs(determinant(T)) > SINGULAR_T * norm2 * sqrt(norm2)) return uOrigin + inverse(T) * b;
  if (!(norm2 > 0.0)) return uOrigin;
  const mat3 Tt = transpose(T);
  return uOrigin + inverse(Tt * T + SINGULAR_T * norm2 * mat3(1.0)) * (Tt * b);
#else
  // T = [[y0, y2 + y3], [y2 - y3, y1]], b = (y4, y5).
  const mat2 T = transpose(mat2(y[0], y[2] + y[3], y[2] - y[3], y[1]));
  const vec2 b = vec2(y[4], y[5]);
  const float norm2 = dot(T[0], T[0]) + dot(T[1], T[1]);
  if (abs(determinant(T)) > SINGULAR_T * norm2) return vec3(uOrigin.xy + inverse(T) * b, 0.0);
  if (!(norm2 > 0.0)) return vec3(uOrigin.xy, 0.0);
  const mat2 Tt = transpose(T);
  return vec3(uOrigin.xy + inverse(Tt * T + SINGULAR_T * norm2 * mat2(1.0)) * (Tt * b), 0.0);
#endif
}

void main() {
  const uint lane = gl_LocalInvocationID.x;
  const uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
  const uint point = group * uint(GROUP_POINTS) + gl_LocalInvocationID.y;  // within this chunk
  const bool inRange = point < uNumPoints;

  float y[OUTPUTS];
  for (int j = 0; j < OUTPUTS; ++j) y[j] = 0.0;
#if SPARSE
  if (inRange) {
    const uint row = point * uRowEntries;
    for (uint k = lane; k < uRowEntries; k += uint(ROW_THREADS)) {
      const float c = C[row + k];
      const uint column = entryColumns[row + k];
      if (column < uMainColumns) {
        const uint w = column * uint(MAIN_OUTPUTS);
        for (int j = 0; j < MAIN_OUTPUTS; ++j) y[MAIN_OFFSET + j] += c * W[w + uint(j)];
      } else {
        const uint w = uMainColumns * uint(MAIN_OUTPUTS) + (column - uMainColumns) * uint(OUTPUTS);
        for (int j = 0; j < OUTPUTS; ++j) y[j] += c * W[w + uint(j)];
      }
    }
  }
#else
  if (inRange) {
    const uint row = point * (uMainColumns + uTailColumns);
    for (uint k = lane; k < uMainColumns; k += uint(ROW_THREADS)) {
      const float c = C[row + k];
      const uint w = k * uint(MAIN_OUTPUTS);
      for (int j = 0; j < MAIN_OUTPUTS; ++j) y[MAIN_OFFSET + j] += c * W[w + uint(j)];
    }
    const uint tailW = uMainColumns * uint(MAIN_OUTPUTS);
    for (uint k = lane; k < uTailColumns; k += uint(ROW_THREADS)) {
      const float c = C[row + uMainColumns + k];
      const uint w = tailW + k * uint(OUTPUTS);
      for (int j = 0; j < OUTPUTS; ++j) y[j] += c * W[w + uint(j)];
    }
  }
#endif

#if ROW_THREADS > 1
  // Tree reduction over the lanes of each point (every invocation reaches every barrier).
  const uint slot = gl_LocalInvocationID.y;
  for (int j = 0; j < OUTPUTS; ++j) partial[slot][j][lane] = y[j];
  barrier();
  for (uint stride = uint(ROW_THREADS) / 2u; stride > 0u; stride /= 2u) {
    if (lane < stride)
      for (int j = 0; j < OUTPUTS; ++j) partial[slot][j][lane] += partial[slot][j][lane + stride];
    barrier();
  }
  if (!inRange || lane != 0u) return;
  for (int j = 0; j < OUTPUTS; ++j) y[j] = partial[slot][j][0];
#else
  if (!inRange) return;
#endif

  const vec3 x = finish(y);
  const uint row = uFirstPoint + point;
  if (row < uMeshPoints) {
    positions[3u * row] = x.x;
    positions[3u * row + 1u] = x.y;
    positions[3u * row + 2u] = x.z;
  } else {
    const uint at = 3u * (row - uMeshPoints);
    extra[at] = x.x;
    extra[at + 1u] = x.y;
    extra[at + 2u] = x.z;
  }
}
