#!/usr/bin/env python3
"""Time SciPy's shift-invert eigen solver on the matrices `chipflex reduce` exported.

The side-by-side check of the reduction's speed (docs/performance.md, "Against SciPy"):
`chipflex reduce MESH -o BODY.h5 ... --export-matrices DIR` writes K and M (lower
triangles, Matrix Market, docs/export_matrices.md); this script solves the same
generalised problem K x = lambda M x for the same number of modes with
scipy.sparse.linalg.eigsh in shift-invert mode about 0 (SuperLU factors K, ARPACK's
implicitly restarted Lanczos), and prints the wall time of the solve and the
frequencies, so that they can be set against `chipflex reduce`'s stage timings.

    python3 bench/compare_scipy_eigsh.py DIR [--modes 20] [--tol 1e-8]

Reading the text files is not timed (the comparison is of the solvers). Needs Debian's
python3-scipy.
"""
import argparse
import math
import resource
import sys
import time

import numpy as np
import scipy
import scipy.io
import scipy.sparse as sp
import scipy.sparse.linalg as sla


def symmetric(path):
    """The full matrix from a Matrix Market file of its lower triangle."""
    # mmread of a `symmetric` file already mirrors the triangle.
    return sp.csc_matrix(scipy.io.mmread(path))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir", help="folder with K.mtx and M.mtx from --export-matrices")
    parser.add_argument("--modes", type=int, default=20)
    parser.add_argument("--tol", type=float, default=1e-8,
                        help="ARPACK's relative tolerance (chipflex reduce uses 1e-8)")
    args = parser.parse_args()

    t0 = time.perf_counter()
    K = symmetric(args.dir + "/K.mtx")
    M = symmetric(args.dir + "/M.mtx")
    reading = time.perf_counter() - t0
    print(f"scipy {scipy.__version__}, numpy {np.__version__}: {K.shape[0]} rows, "
          f"K {K.nnz} and M {M.nnz} entries (full), read in {reading:.1f} s (not timed)")
    sys.stdout.flush()

    t0 = time.perf_counter()
    lam, _ = sla.eigsh(K, k=args.modes, M=M, sigma=0.0, which="LM", tol=args.tol)
    solve = time.perf_counter() - t0
    peak_gib = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 2**20
    freqs = np.sqrt(np.sort(lam)) / (2 * math.pi)
    print(f"eigsh shift-invert (sigma = 0, SuperLU + ARPACK): {solve:.1f} s wall, "
          f"peak memory {peak_gib:.2f} GiB")
    for i, f in enumerate(freqs, start=1):
        print(f"  mode {i:2d} {f:14.6f} Hz")


if __name__ == "__main__":
    main()
