// What lets the same code run on the CPU and in CUDA kernels: SOMICAGE_HD marks functions for both sides when
// nvcc compiles them and is empty for a plain C++ compiler, so the host tests check the device math with g++.
#pragma once

#ifdef __CUDACC__
#define SOMICAGE_HD __host__ __device__
#else
#define SOMICAGE_HD
#endif
