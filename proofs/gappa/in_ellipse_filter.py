#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Writes proofs/gappa/in_ellipse_filter.g: the Gappa model of in_ellipse_filter, one line per
# operation of predicates/in_ellipse.hpp's statements, with the hints that split each error.
# Rerun after a change of the filter's expression; the CTest test proofs.in_ellipse_filter checks
# the result against predicates/filter_constants.hpp.
import pathlib
here = pathlib.Path(__file__).resolve().parent
lines=[]; hyps=[]; goals=[]; hints=[]
u=[0]
def prod(name, a, b, A, B):
    u[0]+=1; k=u[0]
    lines.append(f"{name} = rnd({a} * {b}) + u{k};")
    hints.append(f"{name} - {A} * {B} -> (rnd({a} * {b}) - {a} * {b}) + u{k} + ({a} * {b} - {A} * {B});")
    goals.append(name)
    return (name, f"({A} * {B})")
def add(name, x, X, y, Y, op='+'):
    lines.append(f"{name} = rnd({x} {op} {y});")
    hints.append(f"{name} - ({X} {op} {Y}) -> ({name} - ({x} {op} {y})) + (({x} - {X}) {op} ({y} - {Y}));")
    goals.append(name)
    return (name, f"({X} {op} {Y})")
body=[]
def lift(p):
    P=p.upper()[0]+p[1:]
    dx, dy = f"{p}dx", f"{p}dy"; DX, DY = f"{P}dx", f"{P}dy"
    lines.append(f"# const double {p}lift = metric_lift({dx}, {dy}, m);")
    t1,T1 = prod(f"m11_{dx}", "m11", dx, "m11", DX)
    t2,T2 = prod(f"m11_{dx}_{dx}", t1, dx, T1, DX)
    t3,T3 = prod(f"m12_{dx}", "m12x2", dx, "m12x2", DX)
    t4,T4 = prod(f"m12_{dx}_{dy}", t3, dy, T3, DY)
    t5,T5 = prod(f"m22_{dy}", "m22", dy, "m22", DY)
    t6,T6 = prod(f"m22_{dy}_{dy}", t5, dy, T5, DY)
    s1,S1 = add(f"{p}lift_12", t2, T2, t4, T4)
    s,S = add(f"{p}lift", s1, S1, t6, T6)
    return s,S
la,LA = lift('a'); lb,LB = lift('b'); lc,LC = lift('c')
lines.append("# det = alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) + clift * (adx * bdy - bdx * ady);")
def minor(name, a,b,c,d):
    A,B,C,D=[x[0].upper()+x[1:] for x in (a,b,c,d)]
    p1,P1=prod(f"{a}_{b}", a,b,A,B); p2,P2=prod(f"{c}_{d}", c,d,C,D)
    return add(name, p1,P1,p2,P2,'-')
ma,MA=minor("minor_a","bdx","cdy","cdx","bdy")
mb,MB=minor("minor_b","cdx","ady","adx","cdy")
mc,MC=minor("minor_c","adx","bdy","bdx","ady")
ta,TA=prod("term_a",la,ma,LA,MA)
tb,TB=prod("term_b",lb,mb,LB,MB)
tc,TC=prod("term_c",lc,mc,LC,MC)
sab,SAB=add("sum_ab",ta,TA,tb,TB)
lines.append(f"det = rnd(sum_ab + term_c);")
lines.append(f"Det = {SAB} + {TC};")
hints.append(f"det - Det -> (det - (sum_ab + term_c)) + ((sum_ab - {SAB}) + (term_c - {TC}));")
n=u[0]
H="""# proofs/gappa/in_ellipse_filter.g: Gappa model of the stage-A filter
# exactmesh::predicates::in_ellipse_filter (predicates/in_ellipse.hpp), written by
# proofs/gappa/in_ellipse_filter.py from the filter's statements, one line per operation (as in
# incircle_filter.g); the hints split every error into the operation's rounding, its underflow
# term and the propagated error of its operands.
#
# Proves: with all coordinate differences scaled by one power of two so that
#   mc = max(maxx, maxy) lies in [1, 2), and the metric entries by another so that
#   mm = max(|M11|, |M12|, |M22|) lies in [1, 2),
#     |det - Det| <= in_ellipse_filter_eps   and no intermediate overflows below in_ellipse_filter_max,
# where det is the double the filter computes and Det the exact determinant
# det [p - d, q(p - d)] of the exact differences and the (exact, double) metric entries.
# proofs/invariants/filters.md, section 6, turns this into the soundness of the filter.
#
# Model: as in incircle_filter.g, with two more inputs:
# - m11, m12, m22 are the metric's doubles (scaled; exact inputs, no rounding), each at most
#   2 - 2^-52 in magnitude; m12x2 = 2 * m12 is exact (a power-of-two scaling with no underflow;
#   its overflow is among the goals).
# - Every product has degree at most 5 in the scaled inputs (4 in the differences, 1 in the
#   metric), so its underflow term is at most 2^(-1074 + 5 L) when both maxima are at least
#   in_ellipse_filter_min = 2^-L (proofs/check_constants.cmake, degree 5).
#
# Placeholders filled in by proofs/check_constants.cmake (CTest test proofs.in_ellipse_filter):
#     @EPS@        in_ellipse_filter_eps
#     @UNDERFLOW@  2^(-1074 + 5 L), L = -log2(in_ellipse_filter_min)
#     @OVERFLOW@   2^(1023 - 5 M), M = log2(in_ellipse_filter_max)
#@ -Eprecision=200
#@ -Echange-threshold=0
#@ -Eno-auto-dichotomy

@rnd = float<53, ne>;

adx = rnd(Adx); ady = rnd(Ady); bdx = rnd(Bdx); bdy = rnd(Bdy);
cdx = rnd(Cdx); cdy = rnd(Cdy);
m12x2 = 2 * m12;

"""
out=H+"\n".join(lines)+"\n\n"
big="18014398509481983b-53"; sm="9007199254740991b-52"
hy=[f"|{v}| <= {big}" for v in "Adx Ady Bdx Bdy Cdx Cdy".split()]
hy+=[f"|{v}| <= {sm}" for v in "adx ady bdx bdy cdx cdy m11 m12 m22".split()]
hy+=[f"|u{k}| <= @UNDERFLOW@" for k in range(1,n+1)]
gl=["|det - Det| <= @EPS@"]+[f"|{g}| <= @OVERFLOW@" for g in ["m12x2"]+goals+["det"]]
def wrap(items, sep, indent):
    res=[]; cur=indent
    for i,it in enumerate(items):
        piece = it + (sep if i < len(items)-1 else "")
        if len(cur)+len(piece) > 98:
            res.append(cur.rstrip()); cur=indent
        cur+=piece
    res.append(cur.rstrip())
    return "\n".join(res)
out+="{ "+wrap(hy," /\\ ","  ").lstrip()+"\n  -> "+wrap(gl," /\\ ","     ").lstrip()+" }\n\n"
out+="# Hints.\n"+"\n".join(hints)+"\n"
(here / 'in_ellipse_filter.g').write_text(out)
