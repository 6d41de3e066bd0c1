#!/usr/bin/env python3
"""Barsky's Beta-spline basis derived from its definition in exact rational arithmetic.

The matrices in tests/spline/basis_matrices.cpp ("Beta-spline matrices with b1 != 1 ...") and
tests/kernel/kernel.cpp were printed by this script; it shares nothing with the library.

Definition (Barsky 1981, as the memo states it): the segment between knots i and i+1 is
    Q_i(u) = sum_{r=-2..1} V_{i+r} b_r(u),  u in [0, 1],  each b_r a cubic,
and at every joint, for every control polygon V,
    Q_{i+1}(0)   = Q_i(1)
    Q_{i+1}'(0)  = b1 Q_i'(1)                    (bias: the velocity ratio)
    Q_{i+1}''(0) = b1^2 Q_i''(1) + b2 Q_i'(1)    (tension)
plus sum_r b_r(u) = 1 (the curve does not depend on where the origin is). Taking the
coefficient of each V_{i+r}, r = -2..2 (b_{-3} = b_2 = 0), gives 15 homogeneous equations in
the 16 polynomial coefficients; the partition of unity adds 4. The system has exactly one
solution (checked: full column rank, consistent). Column c of the memo's matrix is b_{c-2},
row j the coefficient of u^(3-j).

Run: python3 tests/spline/beta_derivation.py
"""
from fractions import Fraction as F


def solve(A, b):
    """The unique solution of A x = b by exact Gauss-Jordan elimination (asserts it exists)."""
    n = len(A[0])
    rows = [r[:] + [bb] for r, bb in zip(A, b)]
    rank = 0
    for c in range(n):
        p = next((i for i in range(rank, len(rows)) if rows[i][c] != 0), None)
        if p is None:
            continue
        rows[rank], rows[p] = rows[p], rows[rank]
        pv = rows[rank][c]
        rows[rank] = [x / pv for x in rows[rank]]
        for i in range(len(rows)):
            if i != rank and rows[i][c] != 0:
                f = rows[i][c]
                rows[i] = [x - f * y for x, y in zip(rows[i], rows[rank])]
        rank += 1
    assert rank == n, "the constraints do not fix the basis"
    assert all(rows[i][n] == 0 for i in range(rank, len(rows))), "the constraints are inconsistent"
    return [rows[i][n] for i in range(n)]


def beta(b1, b2):
    """The 4x4 matrix (rows u^3 .. 1, columns V_{i-2} .. V_{i+1}) as Fractions."""
    def at(k, u, order):  # coefficients of the order-th derivative of b_{k-2} at u
        row = [F(0)] * 16
        if 0 <= k <= 3:
            for j, e in enumerate((3, 2, 1, 0)):
                if e >= order:
                    f = 1
                    for t in range(order):
                        f *= e - t
                    row[4 * k + j] = f * F(u) ** (e - order)
        return row

    A, rhs = [], []
    for r in range(-2, 3):
        left, right = r + 2, r + 1  # b_r at the end of Q_i, b_{r-1} at the start of Q_{i+1}
        A.append([y - x for x, y in zip(at(left, 1, 0), at(right, 0, 0))])
        A.append([y - b1 * x for x, y in zip(at(left, 1, 1), at(right, 0, 1))])
        A.append([z - b1 * b1 * x - b2 * y for x, y, z in zip(at(left, 1, 2), at(left, 1, 1), at(right, 0, 2))])
        rhs += [F(0)] * 3
    for j in range(4):
        A.append([F(1) if i % 4 == j else F(0) for i in range(16)])
        rhs.append(F(1 if j == 3 else 0))
    x = solve(A, rhs)
    return [[x[4 * c + j] for c in range(4)] for j in range(4)]


if __name__ == "__main__":
    for b1, b2 in [(F(1), F(0)), (F(2), F(1)), (F(1, 2), F(3)), (F(3), F(0)), (F(2, 3), F(5, 2))]:
        d = b2 + 2 * b1 ** 3 + 4 * b1 ** 2 + 4 * b1 + 2
        print(f"b1 = {b1}, b2 = {b2} (memo's d = {d}):")
        for row in beta(b1, b2):
            print("   ", ", ".join(str(v) for v in row))
