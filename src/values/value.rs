//! Runtime values: numbers and matrices with their kind, tuples, mechanisms,
//! user functions and symbolic expressions over `given` names.

use std::rc::Rc;

use nalgebra::DMatrix;

use super::symbolic::Tree;
use crate::check::ty::Kind;
use crate::mech::Mechanism;
use crate::syntax::ast::Expr;

/// A symbolic expression over `given` names, with values as constants.
pub type Sym = Tree<Value>;

/// A user function `f(x, y) = body`.
#[derive(Debug, Clone, PartialEq)]
pub struct UserFn {
    pub name: String,
    pub params: Vec<String>,
    pub body: Expr,
}

/// A value. Numbers of every shape are a matrix plus a [`Kind`] that says
/// what the book calls it (a scalar is 1×1, a vector n×1).
#[derive(Debug, Clone)]
pub enum Value {
    Num {
        kind: Kind,
        m: DMatrix<f64>,
    },
    Bool(bool),
    Tuple(Vec<Value>),
    Mech(Rc<Mechanism>),
    /// An expression over `given` symbols (LANGUAGE.md §7).
    Sym(Sym),
    /// A scalar, vector or matrix whose entries are symbolic scalars in
    /// canonical form (`Rotz(theta)`), with its kind (LANGUAGE.md §7).
    Formula {
        kind: Kind,
        m: crate::sym::Mat,
    },
}

impl PartialEq for Value {
    /// Structural equality (numbers exactly, symbolic values by their
    /// trees and canonical forms; mechanisms and functions by identity).
    fn eq(&self, other: &Value) -> bool {
        match (self, other) {
            (Value::Num { kind: a, m: x }, Value::Num { kind: b, m: y }) => a == b && x == y,
            (Value::Bool(a), Value::Bool(b)) => a == b,
            (Value::Tuple(a), Value::Tuple(b)) => a == b,
            (Value::Mech(a), Value::Mech(b)) => Rc::ptr_eq(a, b),
            (Value::Sym(a), Value::Sym(b)) => a == b,
            (Value::Formula { kind: a, m: x }, Value::Formula { kind: b, m: y }) => {
                a == b && x == y
            }
            _ => false,
        }
    }
}

impl Value {
    pub fn scalar(x: f64) -> Value {
        Value::Num {
            kind: Kind::Scalar,
            m: DMatrix::from_element(1, 1, x),
        }
    }
    /// A value of `kind` from any nalgebra matrix.
    pub fn num<R: nalgebra::Dim, C: nalgebra::Dim, S>(
        kind: Kind,
        m: &nalgebra::Matrix<f64, R, C, S>,
    ) -> Value
    where
        S: nalgebra::RawStorage<f64, R, C>,
    {
        let (r, c) = m.shape();
        Value::Num {
            kind,
            m: DMatrix::from_iterator(r, c, m.iter().copied()),
        }
    }
    /// A column vector.
    pub fn vector(kind: Kind, v: &[f64]) -> Value {
        Value::Num {
            kind,
            m: DMatrix::from_column_slice(v.len(), 1, v),
        }
    }
    /// The kind this value has at run time.
    pub fn kind(&self) -> Kind {
        match self {
            Value::Num { kind, .. } => kind.clone(),
            Value::Bool(_) => Kind::Bool,
            Value::Tuple(vs) => Kind::Tuple(vs.iter().map(Value::kind).collect()),
            Value::Mech(_) => Kind::Mechanism,
            Value::Sym(_) => Kind::Unknown,
            Value::Formula { kind, .. } => kind.clone(),
        }
    }
    /// The number of a scalar value.
    pub fn as_scalar(&self) -> Option<f64> {
        match self {
            Value::Num { m, .. } if m.len() == 1 => Some(m[0]),
            _ => None,
        }
    }
    pub fn as_matrix(&self) -> Option<&DMatrix<f64>> {
        match self {
            Value::Num { m, .. } => Some(m),
            _ => None,
        }
    }
    pub fn is_symbolic(&self) -> bool {
        matches!(self, Value::Sym(_))
    }
}
