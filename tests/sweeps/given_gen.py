#!/usr/bin/env python3
"""Differential sweep: `given a, b; X = e; a = ..; b = ..; X` against the numbers first."""
import json, os, random, subprocess, sys, math, re

BIN = os.environ.get("CHASLES", "target/debug/chasles")
R = random.Random(int(sys.argv[1]) if len(sys.argv) > 1 else 1)
VALUES = ["0.37", "-1.2", "0", "pi", "-pi", "pi/2", "2", "0.5", "1e-9", "-0.7", "3", "1/3", "2 pi", "1.1"]


def pick(xs):
    return R.choice(xs)


def atom():
    return pick(["a", "b", "a", "b", "0.3", "2", "-1", "pi/4", "(a + b)", "(a*b)", "(2*a)", "(a - 1)"])


def S(d):
    """A scalar expression."""
    if d <= 0:
        return atom()
    k = R.randrange(34)
    s = lambda: S(d - 1)
    if k < 4: return atom()
    if k == 4: return f"sin({s()})"
    if k == 5: return f"cos({s()})"
    if k == 6: return f"tan({s()})"
    if k == 7: return f"atan2({s()}, {s()})"
    if k == 8: return f"sqrt({s()})"
    if k == 9: return f"abs({s()})"
    if k == 10: return f"({s()} + {s()})"
    if k == 11: return f"({s()} * {s()})"
    if k == 12: return f"({s()} / {pick(['2', '3', '(a + 5)', 'b', 'a'])})"
    if k == 13: return f"{s()}^{pick(['2', '3', '-1', '0'])}"
    if k == 14: return f"norm({V3(d - 1)})"
    if k == 15: return f"det({M3(d - 1)})"
    if k == 16: return f"trace({M3(d - 1)})"
    if k == 17: return f"dot({V3(d - 1)}, {V3(d - 1)})"
    if k == 18: return f"{SO3(d - 1)}[{R.randint(1, 3)}, {R.randint(1, 3)}]"
    if k == 19: return f"{V3(d - 1)}[{R.randint(1, 3)}]"
    if k == 20: return f"{SE3(d - 1)}[{R.randint(1, 3)}, 4]"
    if k == 21: return f"norm({V6(d - 1)})"
    if k == 22: return f"AxisAng3({V3(d - 1)})[2]"
    if k == 23: return f"det({SE3(d - 1)})"
    if k == 24: return f"trace({SE3(d - 1)})"
    if k == 25: return f"-{s()}"
    if k == 26: return f"({s()} - {s()})"
    if k == 27: return f"trace({ADJ(d - 1)})"
    if k == 28: return f"[{s()}*k for k in 1:3][{R.randint(1, 3)}]"
    if k == 29: return f"AxisAng6({V6(d - 1)})[2]"
    if k == 30: return f"det({ADJ(d - 1)})"
    if k == 31: return f"{M3(d - 1)}[{R.randint(1, 3)}, {R.randint(1, 3)}]"
    if k == 32: return f"asin({s()} / 10)"
    return f"acos({s()} / 10)"


def V3(d):
    if d <= 0:
        return f"({atom()}, {atom()}, {atom()})"
    k = R.randrange(16)
    if k < 2: return f"({S(d-1)}, {S(d-1)}, {S(d-1)})"
    if k == 2: return f"{SO3(d-1)} * {V3(d-1)}"
    if k == 3: return f"cross({V3(d-1)}, {V3(d-1)})"
    if k == 4: return f"so3ToVec({so3(d-1)})"
    if k == 5: return f"TransToRp({SE3(d-1)})[2]"
    if k == 6: return f"AxisAng3({V3(d-1)})[1]"
    if k == 7: return f"{SE3(d-1)}[1:3, 4]"
    if k == 8: return f"{SO3(d-1)}[:, {R.randint(1, 3)}]"
    if k == 9: return f"{S(d-1)} * {V3(d-1)}"
    if k == 10: return f"({V3(d-1)} + {V3(d-1)})"
    if k == 11: return f"{V6(d-1)}[{pick(['1:3', '4:6'])}]"
    if k == 12: return f"vee({so3(d-1)})"
    if k == 13: return f"{M3(d-1)} * {V3(d-1)}"
    if k == 14: return f"{V3(d-1)} / {pick(['2', '(a^2 + 1)'])}"
    return f"({atom()}, 0, 0)"


def V6(d):
    if d <= 0:
        return f"({atom()}, {atom()}, {atom()}, {atom()}, {atom()}, {atom()})"
    k = R.randrange(8)
    if k == 0: return f"({S(d-1)}, 0, {S(d-1)}, {S(d-1)}, 1, {S(d-1)})"
    if k == 1: return f"{ADJ(d-1)} * {V6(d-1)}"
    if k == 2: return f"se3ToVec({se3(d-1)})"
    if k == 3: return f"AxisAng6({V6(d-1)})[1]"
    if k == 4: return f"{S(d-1)} * {V6(d-1)}"
    if k == 5: return f"({V6(d-1)} - {V6(d-1)})"
    if k == 6: return f"(0, 0, 0, {S(d-1)}, {S(d-1)}, {S(d-1)})"
    return f"(0, 0, 1, {S(d-1)}, {S(d-1)}, 0)"


def SO3(d):
    if d <= 0:
        return f"{pick(['Rotx', 'Roty', 'Rotz'])}({atom()})"
    k = R.randrange(16)
    if k < 3: return f"{pick(['Rotx', 'Roty', 'Rotz'])}({S(d-1)})"
    if k == 3: return f"Rot({V3(d-1)}, {S(d-1)})"
    if k == 4: return f"Rot({pick(['x', 'y', 'z'])}, {S(d-1)})"
    if k == 5: return f"MatrixExp3({so3(d-1)})"
    if k == 6: return f"exp({so3(d-1)})"
    if k == 7: return f"{SO3(d-1)} * {SO3(d-1)}"
    if k == 8: return f"RotInv({SO3(d-1)})"
    if k == 9: return f"{SO3(d-1)}.T"
    if k == 10: return f"inv({SO3(d-1)})"
    if k == 11: return f"TransToRp({SE3(d-1)})[1]"
    if k == 12: return f"{SO3(d-1)}^{pick(['2', '-1', '3', '0', 'T'])}"
    if k == 13: return f"MatrixExp3({V3(d-1)})"
    if k == 14: return f"{SE3(d-1)}[1:3, 1:3]"
    return f"exp([{V3(d-1)}] {S(d-1)})"


def so3(d):
    if d <= 0:
        return f"VecToso3(({atom()}, {atom()}, {atom()}))"
    k = R.randrange(7)
    if k == 0: return f"VecToso3({V3(d-1)})"
    if k == 1: return f"[{V3(d-1)}]"
    if k == 2: return f"log({SO3(d-1)})"
    if k == 3: return f"skew({V3(d-1)}) * {S(d-1)}"
    if k == 4: return f"MatrixLog3({SO3(d-1)})"
    if k == 5: return f"({so3(d-1)} + {so3(d-1)})"
    return f"-{so3(d-1)}"


def SE3(d):
    if d <= 0:
        return f"RpToTrans({pick(['Rotx', 'Roty', 'Rotz'])}({atom()}), ({atom()}, {atom()}, {atom()}))"
    k = R.randrange(13)
    if k < 2: return f"RpToTrans({SO3(d-1)}, {V3(d-1)})"
    if k == 2: return f"MatrixExp6({se3(d-1)})"
    if k == 3: return f"exp({se3(d-1)})"
    if k == 4: return f"{SE3(d-1)} * {SE3(d-1)}"
    if k == 5: return f"TransInv({SE3(d-1)})"
    if k == 6: return f"inv({SE3(d-1)})"
    if k == 7: return f"Trans({V3(d-1)})"
    if k == 8: return f"[{SO3(d-1)}, {V3(d-1)}; 0, 1]"
    if k == 9: return f"{SE3(d-1)}^{pick(['2', '-1'])}"
    if k == 10: return f"MatrixExp6({V6(d-1)})"
    if k == 11: return f"exp([{V6(d-1)}] {S(d-1)})"
    return f"RpToTrans(eye(3), {V3(d-1)})"


def se3(d):
    if d <= 0:
        return f"VecTose3({V6(0)})"
    k = R.randrange(6)
    if k == 0: return f"VecTose3({V6(d-1)})"
    if k == 1: return f"[{V6(d-1)}]"
    if k == 2: return f"log({SE3(d-1)})"
    if k == 3: return f"MatrixLog6({SE3(d-1)})"
    if k == 4: return f"VecTose3({V6(d-1)}) * {S(d-1)}"
    return f"({se3(d-1)} - {se3(d-1)})"


def ADJ(d):
    k = R.randrange(4)
    if k < 2: return f"Ad({SE3(max(d-1, 0))})"
    if k == 2: return f"Adjoint({SE3(max(d-1, 0))})"
    return f"inv(Ad({SE3(max(d-1, 0))}))"


def M3(d):
    k = R.randrange(8)
    if k == 0: return f"[{atom()}, {atom()}, 0; 0, {atom()}, 1; 1, 0, {atom()}]"
    if k == 1: return f"{so3(max(d-1,0))}^2"
    if k == 2: return f"({SO3(max(d-1,0))} + {so3(max(d-1,0))})"
    if k == 3: return f"inv([{atom()}, 1, 0; 0, 2, 1; 1, 0, 3])"
    if k == 4: return f"transpose({SO3(max(d-1,0))})"
    if k == 5: return f"({SO3(max(d-1,0))} - eye(3))"
    if k == 6: return f"[{atom()}, 1, 0; 0, 2, 1; 1, 0, 3]^{pick(['2', '-1', '3'])}"
    return SO3(max(d - 1, 0))


GENS = [S, S, S, V3, V3, V6, SO3, SO3, so3, SE3, SE3, se3, ADJ, M3]


def item():
    """(kind, expr, defs) one statement to compare."""
    d = R.randint(1, 3)
    g = pick(GENS)
    e = g(d)
    r = R.randrange(16)
    if r == 0:
        return ("diff", e, None)
    if r == 1:
        return ("plain", f"[{S(d-1).replace('a', 'k*a') if False else S(d-1)} * k for k in 1:3]", None)
    if r == 2:
        # user function
        body = re.sub(r"\ba\b", "x", S(d - 1) if R.random() < 0.5 else g(d - 1))
        return ("fun", f"F(x) = {body}", f"F({atom()})")
    if r == 3:
        # subs with a third symbol c
        body = e.replace("b", "c", 1)
        return ("subs", f"subs({body}, c, {pick(['0.25', '0', 'pi', '-1'])})", None)
    if r == 4:
        return ("plain", f"({e}, {S(0)})", None)
    if r == 5:
        f = pick(["sin", "cos", "Rotz", "Rotx", "sqrt", "abs", "exp"])
        if f == "exp":
            return ("plain", f"[exp([(0, 0, 1, k*a, b, 0)] a) for k in 1:{R.randint(1, 3)}]", None)
        return ("plain", f"[{f}(k*a + b) for k in 1:3]", None)
    if r == 6:
        # pure translations and their logs / adjoints / axis-angle forms
        p = V3(d - 1)
        return ("plain", pick([f"log(Trans({p}))", f"MatrixLog6(Trans({p}))", f"Ad(Trans({p}))",
                               f"AxisAng6(se3ToVec(log(Trans({p}))))", f"MatrixExp6([(0, 0, 0, {S(0)}, {S(0)}, {S(0)})])",
                               f"TransInv(Trans({p})) * Trans({p})", f"log(RpToTrans(Rotz(a - a), {p}))"]), None)
    if r == 7:
        # half turns: log at pi, AxisAng3 of pi-rotations
        ax = pick(["Rotx", "Roty", "Rotz"])
        return ("plain", pick([f"log({ax}(a))", f"MatrixLog3({ax}(a))", f"log({ax}(a) * {ax}(b))",
                               f"MatrixLog6(RpToTrans({ax}(a), (a, b, 1)))", f"log(Rot((1, a, b), pi))",
                               f"AxisAng3(MatrixLog3({ax}(a)))[2]", f"MatrixLog3(Rot((1, 2, 2)/3, a))"]), None)
    if r == 9:
        return ("plain", pick([f"({S(d-1)})^({S(0)})", f"2^({S(d-1)})", f"({S(d-1)} < {S(d-1)})",
                               f"({SO3(d-1)} == {SO3(d-1)})", f"({S(d-1)} == {S(d-1)})", f"({V3(d-1)} ≈ {V3(d-1)})",
                               f"Rot((0, 0, 1), {S(d-1)})", f"exp([(0, 0, 1)] {S(d-1)})", f"euler_zyx({SO3(d-1)})",
                               f"rpy({SO3(d-1)})", f"quat({SO3(d-1)})", f"screw_params({V6(d-1)})",
                               f"inv({M3(d-1)})", f"det(inv({SE3(d-1)}))", f"{SE3(d-1)}^{{-1}} * {V3(d-1)}",
                               f"Ad({SE3(d-1)}).T * {V6(d-1)}", f"cross({V3(d-1)}, {V3(d-1)})[{R.randint(1,3)}]",
                               f"mod({S(d-1)}, 2)" if False else f"atan2({S(d-1)}, 0)"]), None)
    if r == 8:
        body = pick(["Rotz(x) * Rotx(y)", "RpToTrans(Rotz(x), (y, x, 1))", "sin(x) * y + cos(y)",
                     "Ad(RpToTrans(Roty(x), (0, y, 0)))", "[x, y; y, x]^-1", "cross((x, y, 1), (y, 1, x))"])
        return ("fun", f"F(x, y) = {body}", f"F({S(d-1)}, {atom()})")
    return ("plain", e, None)


def scripts(n_items, va, vb, mode="all"):
    items = [item() for _ in range(n_items)]
    sym = ["given a", "given b", "given c"]
    num = ["given c", f"a = {va}", f"b = {vb}"]
    for i, (kind, e, extra) in enumerate(items, 1):
        x = f"X{i}"
        y = f"Y{i}" if mode == "partly" else x
        if kind == "fun":
            fname = f"F{i}"
            fdef = e.replace("F(x", f"{fname}(x", 1)
            call = extra.replace('F(', fname + '(', 1)
            sym.append(fdef); num.append(fdef); num.append(f"{x} = {call}")
            sym.append(f"{y} = subs({call}, a, {va})" if mode == "subs" else f"{y} = {call}")
        elif kind == "diff":
            sym.append(f"{y} = subs(diff({e}, a), a, {va})" if mode == "subs" else f"{y} = diff({e}, a)")
            num.append(f"a = ({va}) + 1e-6"); num.append(f"{x}p = {e}")
            num.append(f"a = ({va}) - 1e-6"); num.append(f"{x}m = {e}")
            num.append(f"a = {va}")
        else:
            sym.append(f"{y} = subs({e}, a, {va})" if mode == "subs" else f"{y} = {e}")
            num.append(f"{x} = {e}")
    if mode == "partly":
        sym.append(f"a = {va}")
        sym += [f"X{i} = Y{i}" for i in range(1, len(items) + 1)]
        sym.append(f"b = {vb}")
    elif mode == "subs":
        sym.append(f"b = {vb}")
    else:
        sym += [f"a = {va}", f"b = {vb}"]
    for i, (kind, e, extra) in enumerate(items, 1):
        sym.append(f"X{i}")
        if kind == "diff":
            num.append(f"X{i}p"); num.append(f"X{i}m")
        else:
            num.append(f"X{i}")
    return items, "\n".join(sym) + "\n", "\n".join(num) + "\n"


if __name__ == "__main__":
    pass
