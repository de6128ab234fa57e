#pragma once
// OpenBLAS 0.3.21 (Debian bookworm) does not recognise recent Xeons and falls back to its generic
// Prescott kernels, which halve LibTorch's speed here. Before a model command runs, this restarts
// the program once with OPENBLAS_CORETYPE set to the best kernel family the CPU supports.

namespace graspecmf::apps {

// If OpenBLAS is loaded with its generic kernels, OPENBLAS_CORETYPE is unset and the CPU has
// AVX-512 (SkylakeX) or AVX2 (Haswell): sets the variable and re-executes /proc/self/exe with argv.
// Otherwise (or if the restart fails) returns and the program goes on unchanged.
void prefer_fast_blas_kernels(char** argv);

}  // namespace graspecmf::apps
