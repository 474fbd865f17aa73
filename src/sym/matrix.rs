//! Matrices of canonical expressions and the book's closed forms over them:
//! Rodrigues' formula (3.51) for e^{\[ω̂\]θ}, Proposition 3.16 for e^{\[S\]θ}
//! with G(θ), inverses by transpose (3.23 and the SE(3) inverse of
//! §3.3.1), the adjoint (Definition 3.20), \[x\] (3.30), det and trace.

use super::coef::Coef;
use super::expr::Expr;
use num_traits::{One, Zero};

/// A rows × cols matrix of expressions, row-major.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
pub struct Mat {
    /// Number of rows.
    pub rows: usize,
    /// Number of columns.
    pub cols: usize,
    /// The rows × cols entries, row by row (entry (i, j) at i·cols + j).
    pub data: Vec<Expr>,
}

impl Mat {
    /// The zero matrix.
    pub fn zeros(rows: usize, cols: usize) -> Mat {
        Mat {
            rows,
            cols,
            data: vec![Expr::zero(); rows * cols],
        }
    }
    /// The n×n identity.
    pub fn identity(n: usize) -> Mat {
        let mut m = Mat::zeros(n, n);
        for i in 0..n {
            m.set(i, i, Expr::one());
        }
        m
    }
    /// From rows of equal length (None when ragged or empty).
    pub fn from_rows(rows: Vec<Vec<Expr>>) -> Option<Mat> {
        let cols = rows.first()?.len();
        if rows.iter().any(|r| r.len() != cols) {
            return None;
        }
        Some(Mat {
            rows: rows.len(),
            cols,
            data: rows.into_iter().flatten().collect(),
        })
    }
    /// A column vector.
    pub fn column(v: Vec<Expr>) -> Mat {
        Mat {
            rows: v.len(),
            cols: 1,
            data: v,
        }
    }
    /// A 1×1 matrix.
    pub fn scalar(e: Expr) -> Mat {
        Mat::column(vec![e])
    }
    /// Entry (i, j), 0-based.
    pub fn get(&self, i: usize, j: usize) -> &Expr {
        &self.data[i * self.cols + j]
    }
    /// Sets entry (i, j), 0-based.
    pub fn set(&mut self, i: usize, j: usize, e: Expr) {
        self.data[i * self.cols + j] = e;
    }
    /// The rows.
    pub fn row_vecs(&self) -> Vec<Vec<Expr>> {
        self.data
            .chunks(self.cols.max(1))
            .map(<[Expr]>::to_vec)
            .collect()
    }
    /// Entrywise f.
    pub fn map(&self, f: impl Fn(&Expr) -> Expr) -> Mat {
        Mat {
            rows: self.rows,
            cols: self.cols,
            data: self.data.iter().map(f).collect(),
        }
    }
    /// Aᵀ.
    pub fn transpose(&self) -> Mat {
        let mut m = Mat::zeros(self.cols, self.rows);
        for i in 0..self.rows {
            for j in 0..self.cols {
                m.set(j, i, self.get(i, j).clone());
            }
        }
        m
    }
    /// A + B (or A − B); None when the shapes differ.
    pub fn add(&self, o: &Mat, subtract: bool) -> Option<Mat> {
        if (self.rows, self.cols) != (o.rows, o.cols) {
            return None;
        }
        let data = self
            .data
            .iter()
            .zip(&o.data)
            .map(|(a, b)| if subtract { a.sub(b) } else { a.add(b) })
            .collect();
        Some(Mat { data, ..*self })
    }
    /// k·A for a scalar expression k.
    pub fn scale(&self, k: &Expr) -> Mat {
        self.map(|e| e.mul(k))
    }
    /// A B; None when the inner sizes differ.
    pub fn mul(&self, o: &Mat) -> Option<Mat> {
        if self.cols != o.rows {
            return None;
        }
        let mut m = Mat::zeros(self.rows, o.cols);
        for i in 0..self.rows {
            for j in 0..o.cols {
                let pairs: Vec<(&Expr, &Expr)> = (0..self.cols)
                    .map(|k| (self.get(i, k), o.get(k, j)))
                    .collect();
                m.set(i, j, super::dense::sum_of_products(&pairs));
            }
        }
        Some(m)
    }
    /// The block of rows `r` and columns `c`.
    pub fn block(&self, r: std::ops::Range<usize>, c: std::ops::Range<usize>) -> Mat {
        let mut m = Mat::zeros(r.len(), c.len());
        for (i, ri) in r.clone().enumerate() {
            for (j, cj) in c.clone().enumerate() {
                m.set(i, j, self.get(ri, cj).clone());
            }
        }
        m
    }
    /// Copies `b` into this matrix at (i, j).
    pub fn put(&mut self, i: usize, j: usize, b: &Mat) {
        for r in 0..b.rows {
            for c in 0..b.cols {
                self.set(i + r, j + c, b.get(r, c).clone());
            }
        }
    }
    /// tr A.
    pub fn trace(&self) -> Expr {
        (0..self.rows.min(self.cols)).fold(Expr::zero(), |acc, i| acc.add(self.get(i, i)))
    }
    /// The determinant by cofactor expansion (square matrices up to 6×6).
    pub fn det(&self) -> Option<Expr> {
        if self.rows != self.cols || self.rows > 6 {
            return None;
        }
        Some(det(self))
    }
    /// The largest entry size (for the expression limit).
    pub fn size(&self) -> usize {
        self.data.iter().map(Expr::size).sum()
    }
    /// The deepest nesting of calls in an entry.
    pub fn depth(&self) -> usize {
        self.data.iter().map(Expr::depth).max().unwrap_or(0)
    }
    /// The numbers, when every entry is a real constant.
    pub fn as_f64(&self) -> Option<Vec<f64>> {
        self.data.iter().map(Expr::as_f64).collect()
    }
}

/// A⁻¹ = adj(A)/det(A) for a square matrix up to 4×4 whose determinant
/// is not identically 0 (the inverse where det A ≠ 0, as a formula).
pub fn inverse(m: &Mat) -> Option<Mat> {
    let n = m.rows;
    if n != m.cols || n == 0 || n > 4 {
        return None;
    }
    let d = det(m);
    let inv_d = d.recip()?;
    let mut out = Mat::zeros(n, n);
    for i in 0..n {
        for j in 0..n {
            // cofactor C_ji: the minor without row j and column i
            let mut minor = Mat::zeros(n - 1, n - 1);
            for (r, rr) in (0..n).filter(|&r| r != j).enumerate() {
                for (c, cc) in (0..n).filter(|&c| c != i).enumerate() {
                    minor.set(r, c, m.get(rr, cc).clone());
                }
            }
            let cof = det(&minor).mul(&inv_d).cancel();
            out.set(i, j, if (i + j) % 2 == 0 { cof } else { cof.neg() });
        }
    }
    Some(out)
}

fn det(m: &Mat) -> Expr {
    let n = m.rows;
    match n {
        0 => Expr::one(),
        1 => m.get(0, 0).clone(),
        _ => {
            let mut acc = Expr::zero();
            for j in 0..n {
                let a = m.get(0, j);
                if a.is_zero() {
                    continue;
                }
                // Cofactors grow as n!: past the budget, cut short
                // (discarded by the session: `crate::budget`).
                if crate::budget::stopped() {
                    break;
                }
                let mut minor = Mat::zeros(n - 1, n - 1);
                for r in 1..n {
                    for (cc, c) in (0..n).filter(|&c| c != j).enumerate() {
                        minor.set(r - 1, cc, m.get(r, c).clone());
                    }
                }
                let t = a.mul(&det(&minor));
                acc = if j % 2 == 0 { acc.add(&t) } else { acc.sub(&t) };
            }
            acc
        }
    }
}

/// \[x\] (3.30): the skew-symmetric matrix of a 3-vector.
pub fn skew(w: &[Expr]) -> Mat {
    let z = Expr::zero;
    Mat::from_rows(vec![
        vec![z(), w[2].neg(), w[1].clone()],
        vec![w[2].clone(), z(), w[0].neg()],
        vec![w[1].neg(), w[0].clone(), z()],
    ])
    .unwrap_or_else(|| Mat::zeros(3, 3))
}

/// The vector of a skew-symmetric matrix, (m₃₂, m₁₃, m₂₁).
pub fn unskew(m: &Mat) -> Vec<Expr> {
    vec![
        m.get(2, 1).clone(),
        m.get(0, 2).clone(),
        m.get(1, 0).clone(),
    ]
}

/// \[V\] (3.70): the se(3) matrix of a twist (ω, v).
pub fn twist_matrix(v: &[Expr]) -> Mat {
    let mut m = Mat::zeros(4, 4);
    m.put(0, 0, &skew(&v[..3]));
    m.put(0, 3, &Mat::column(v[3..6].to_vec()));
    m
}

/// Rot(x̂, θ), Rot(ŷ, θ), Rot(ẑ, θ) (§3.2.3.1), `axis` 0, 1, 2.
pub fn rot_axis(axis: usize, theta: &Expr) -> Mat {
    let mut w = vec![Expr::zero(); 3];
    w[axis] = Expr::one();
    rodrigues(&w, theta)
}

/// Rodrigues' formula (3.51): e^{[ω̂]θ} = I + sin θ [ω̂] + (1 − cos θ)[ω̂]²
/// for a unit ω̂.
pub fn rodrigues(w: &[Expr], theta: &Expr) -> Mat {
    let k = skew(w);
    let k2 = k.mul(&k).unwrap_or_else(|| Mat::zeros(3, 3));
    let s = Expr::sin(theta);
    let c = Expr::one().sub(&Expr::cos(theta));
    let mut r = Mat::identity(3);
    for i in 0..9 {
        r.data[i] = r.data[i].add(&k.data[i].mul(&s)).add(&k2.data[i].mul(&c));
    }
    r
}

/// Entries that are constant multiples of one expression: (multiples, θ)
/// with θ's leading coefficient 1, so that [ω]θ splits into ω and θ.
pub(super) fn common_factor(entries: &[Expr]) -> Option<(Vec<Coef>, Expr)> {
    let first = entries.iter().find(|e| !e.is_zero())?;
    let lead = first.terms.values().next()?.clone();
    let theta = first.scale(&lead.inv()?);
    let mut ks = Vec::with_capacity(entries.len());
    for e in entries {
        if e.is_zero() {
            ks.push(Coef::ZERO);
            continue;
        }
        let k = e.terms.values().next()?.clone();
        if e.sub(&theta.scale(&k)).is_zero() {
            ks.push(k);
        } else {
            return None;
        }
    }
    Some((ks, theta))
}

/// The unit axis and angle of exponential coordinates ωθ given as
/// multiples of one expression: ω̂ = ω/‖ω‖ and the angle ‖ω‖θ.
fn axis_angle(ks: &[Coef], theta: &Expr) -> Option<(Vec<Expr>, Expr, Expr)> {
    let n2 = ks.iter().fold(Coef::ZERO, |acc, k| acc.add(&k.mul(k)));
    let n = Expr::sqrt(&Expr::constant(n2)).as_const()?;
    let inv = n.inv()?;
    let axis = ks.iter().map(|k| Expr::constant(k.mul(&inv))).collect();
    Some((axis, theta.scale(&n), Expr::constant(inv)))
}

/// e^{\[ω\]θ} of an so(3) matrix whose entries are multiples of one
/// expression θ (`[w] θ` with numeric w), by Rodrigues (3.51).
pub fn exp3(m: &Mat) -> Option<Mat> {
    let w = unskew(m);
    if w.iter().all(Expr::is_zero) {
        return Some(Mat::identity(3));
    }
    if let Some((ks, theta)) = common_factor(&w) {
        let (axis, angle, _) = axis_angle(&ks, &theta)?;
        return Some(rodrigues(&axis, &angle));
    }
    // [ω̂]θ with ω̂ a `given` vector, assumed a unit axis
    let (axis, angle) = super::axis::symbolic_axis(&w)?;
    Some(rodrigues(&axis, &angle))
}

/// e^{\[S\]θ} of an se(3) matrix whose entries are multiples of one
/// expression θ, by Proposition 3.16: \[e^{\[ω\]θ}, G(θ)v; 0, 1\] with
/// G(θ) = Iθ + (1 − cos θ)\[ω\] + (θ − sin θ)\[ω\]² for ‖ω‖ = 1, and
/// [I, vθ; 0, 1] for ω = 0.
pub fn exp6(m: &Mat) -> Option<Mat> {
    let mut entries = unskew(&m.block(0..3, 0..3));
    entries.extend(m.block(0..3, 3..4).data);
    if entries[..3].iter().all(Expr::is_zero) {
        let mut t = Mat::identity(4);
        t.put(0, 3, &m.block(0..3, 3..4));
        return Some(t);
    }
    // ω = ω̂‖ω‖ with a numeric axis; v = v̂ ‖ω‖θ, v̂ found by dividing by
    // θ exactly (`L1 θ2 / θ2 = L1`, also for a compound θ).
    let Some((ks, theta)) = common_factor(&entries[..3]) else {
        return exp6_symbolic(&entries);
    };
    let (axis, angle, inv) = axis_angle(&ks, &theta)?;
    let v = match common_factor(&entries) {
        // v a numeric multiple of θ as well
        Some((all, t)) if t == theta => all[3..]
            .iter()
            .map(|k| Expr::constant(k.clone()).mul(&inv))
            .collect(),
        _ => {
            let mut v = Vec::with_capacity(3);
            for e in &entries[3..] {
                // exact: `L1 (t2 − π/2) / (t2 − π/2)` = L1
                let x = e.div_exact(&theta)?.mul(&inv);
                if !x.mul(&angle).sub(e).is_zero() {
                    return None;
                }
                v.push(x);
            }
            v
        }
    };
    screw_exp(&axis, &angle, v)
}

/// (3.89) for a unit axis ω̂, an angle θ and v: \[e^{\[ω̂\]θ}, G(θ)v; 0, 1\].
fn screw_exp(axis: &[Expr], angle: &Expr, v: Vec<Expr>) -> Option<Mat> {
    let w = skew(axis);
    let w2 = w.mul(&w)?;
    let c = Expr::one().sub(&Expr::cos(angle));
    let s = angle.sub(&Expr::sin(angle));
    let mut g = Mat::identity(3).scale(angle);
    for i in 0..9 {
        g.data[i] = g.data[i].add(&w.data[i].mul(&c)).add(&w2.data[i].mul(&s));
    }
    let p = g.mul(&Mat::column(v))?;
    Some(rp_to_trans(&rodrigues(axis, angle), &p))
}

/// e^{\[S\]θ} for S = (ω, v) whose ω is a `given` vector's components,
/// assumed a unit axis (Proposition 3.16 with ‖ω‖ = 1): v = (\[S\]θ's
/// linear part)/θ exactly.
fn exp6_symbolic(entries: &[Expr]) -> Option<Mat> {
    let (axis, angle) = super::axis::symbolic_axis(&entries[..3])?;
    let mut names = Vec::new();
    axis.iter().for_each(|a| a.unit_axes(&mut names));
    let mut v = Vec::with_capacity(3);
    for e in &entries[3..] {
        let e = e.assume_unit(&names);
        let x = e.div_exact(&angle)?;
        if x.mul(&angle) != e {
            return None;
        }
        v.push(x);
    }
    screw_exp(&axis, &angle, v)
}

/// [R, p; 0, 1].
pub fn rp_to_trans(r: &Mat, p: &Mat) -> Mat {
    let mut t = Mat::identity(4);
    t.put(0, 0, r);
    t.put(0, 3, p);
    t
}

/// T⁻¹ = [Rᵀ, −Rᵀp; 0, 1] (§3.3.1).
pub fn trans_inv(t: &Mat) -> Option<Mat> {
    let rt = t.block(0..3, 0..3).transpose();
    let p = rt.mul(&t.block(0..3, 3..4))?.map(Expr::neg);
    Some(rp_to_trans(&rt, &p))
}

/// \[Ad_T\] = \[R, 0; \[p\]R, R\] (Definition 3.20).
pub fn adjoint(t: &Mat) -> Option<Mat> {
    let r = t.block(0..3, 0..3);
    let p = t.block(0..3, 3..4);
    let pr = skew(&p.data).mul(&r)?;
    let mut a = Mat::zeros(6, 6);
    a.put(0, 0, &r);
    a.put(3, 0, &pr);
    a.put(3, 3, &r);
    Some(a)
}

/// The small adjoint \[ad_V\] = \[\[ω\], 0; \[v\], \[ω\]\] of a twist V = (ω, v)
/// (Definition 8.1, used with (3.82): d Ad_T = Ad_T \[ad_V\]).
pub fn small_adjoint(v: &[Expr]) -> Mat {
    let (w, lin) = (skew(&v[..3]), skew(&v[3..6]));
    let mut a = Mat::zeros(6, 6);
    a.put(0, 0, &w);
    a.put(3, 0, &lin);
    a.put(3, 3, &w);
    a
}

/// The inverse of an adjoint \[Ad_T\] = \[R, 0; \[p\]R, R\] in closed form,
/// \[Ad_T\]⁻¹ = \[Ad_{T⁻¹}\] = \[Rᵀ, 0; −Rᵀ(\[p\]R)Rᵀ, Rᵀ\] (Proposition
/// 3.20), kept only when it is the inverse (`a` times it is exactly I):
/// None for a 6×6 that is not such a matrix (a general 6×6 inverse is not
/// formed at all).
pub fn adjoint_inverse(a: &Mat) -> Option<Mat> {
    if a.rows != 6 || a.cols != 6 {
        return None;
    }
    let rt = a.block(0..3, 0..3).transpose();
    let q = rt.mul(&a.block(3..6, 0..3))?.mul(&rt)?.map(Expr::neg);
    let mut out = Mat::zeros(6, 6);
    out.put(0, 0, &rt);
    out.put(3, 0, &q);
    out.put(3, 3, &rt);
    (a.mul(&out)? == Mat::identity(6)).then_some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sym::expr::Symbol;

    #[test]
    fn rotation_times_transpose_is_identity() {
        let th = Expr::symbol(Symbol::new("theta"));
        let third = |k| Expr::constant(Coef::rat(crate::sym::coef::Rat::new(k, 3).unwrap()));
        let w: Vec<Expr> = [1, 2, 2].into_iter().map(third).collect();
        let r = rodrigues(&w, &th);
        assert_eq!(r.mul(&r.transpose()).unwrap(), Mat::identity(3));
        assert_eq!(r.det().unwrap(), Expr::one());
    }

    #[test]
    fn exponentials_add_their_angles() {
        let (a, b) = (
            Expr::symbol(Symbol::new("a")),
            Expr::symbol(Symbol::new("b")),
        );
        let s: Vec<Expr> = [0.0, 0.0, 1.0, 0.0, -2.0, 0.5]
            .iter()
            .map(|x| Expr::num(*x))
            .collect();
        let e = |t: &Expr| exp6(&twist_matrix(&s).scale(t)).unwrap();
        assert_eq!(e(&a).mul(&e(&b)).unwrap(), e(&a.add(&b)));
    }
}
