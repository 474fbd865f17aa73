//! The frame graph of a session, built once from its bindings: every bound
//! rotation or transform X_ab (§3.2.1, §3.3.1) is an edge between the frames
//! {a} and {b}; points, twists and wrenches expressed in one frame hang on
//! it. `derive` searches the edges for a chain of frames (§3.3.1, Example
//! 3.2), and the REPL's `:frames` shows the connected components.

use std::collections::{BTreeMap, VecDeque};

use super::env::Env;
use crate::check::ty::{Frame, Frames, Kind};

/// A bound value X_ab that maps coordinates in {b} to {a}.
#[derive(Debug, Clone, PartialEq)]
pub struct Edge {
    /// The bound name, `T_sb`.
    pub name: String,
    /// The frame the value maps to ({a} of X_ab).
    pub from: Frame,
    /// The frame the value maps from ({b} of X_ab).
    pub to: Frame,
    /// SO(3), SE(3), … of the value.
    pub kind: Kind,
}

/// The frames of the session's bindings (`ans` left out: it repeats a
/// named value), in the order of the names.
#[derive(Debug, Clone, Default)]
pub struct FrameGraph {
    /// Values tagged with two different frames.
    pub edges: Vec<Edge>,
    /// Values in one frame: (frame, name).
    pub quantities: Vec<(String, String)>,
}

/// Frame pairs and the names of the values joining them.
type Pairs = BTreeMap<(String, String), Vec<String>>;

/// A connected component of the graph: its frames (sorted), its frame
/// pairs with the names joining them (in the order a walk from the
/// outermost frame meets them), and the quantities of each frame.
#[derive(Debug, Clone, Default)]
pub struct Component {
    /// Its frames' names, sorted.
    pub frames: Vec<String>,
    /// Each frame pair ({a}, {b}) with the names of the values X_ab
    /// joining them, in the order a walk from the outermost frame meets them.
    pub edges: Vec<((String, String), Vec<String>)>,
    /// For each frame, the names of the quantities (points, twists,
    /// wrenches) expressed in it.
    pub quantities: BTreeMap<String, Vec<String>>,
}

impl FrameGraph {
    /// The graph of every binding of `env`.
    pub fn of(env: &Env) -> FrameGraph {
        let mut g = FrameGraph::default();
        for (name, b) in env.bindings() {
            if name == "ans" {
                continue;
            }
            match &b.ty.frames {
                Frames::Pair(a, c) if a != c => g.edges.push(Edge {
                    name: String::from(name),
                    from: *a,
                    to: *c,
                    kind: b.ty.kind,
                }),
                Frames::Pair(a, _) | Frames::One(a) | Frames::Disp(a) => {
                    g.quantities.push((a.to_string(), String::from(name)))
                }
                _ => {}
            }
        }
        g
    }

    /// Every frame named by an edge or a quantity, sorted.
    pub fn frames(&self) -> Vec<String> {
        let mut all: Vec<String> = self
            .edges
            .iter()
            .flat_map(|e| [e.from.to_string(), e.to.to_string()])
            .chain(self.quantities.iter().map(|(a, _)| a.clone()))
            .collect();
        all.sort();
        all.dedup();
        all
    }

    /// The connected components, in the order of their smallest frame.
    pub fn components(&self) -> Vec<Component> {
        let all = self.frames();
        let index = |f: &str| all.binary_search_by(|x| x.as_str().cmp(f)).unwrap_or(0);
        // Union-find over frame indices.
        let mut parent: Vec<usize> = (0..all.len()).collect();
        fn root(parent: &mut [usize], mut i: usize) -> usize {
            while parent[i] != i {
                parent[i] = parent[parent[i]];
                i = parent[i];
            }
            i
        }
        for e in &self.edges {
            let ra = root(&mut parent, index(&e.from.to_string()));
            let rc = root(&mut parent, index(&e.to.to_string()));
            parent[ra.max(rc)] = ra.min(rc);
        }
        let mut comps: BTreeMap<usize, (Component, Pairs)> = BTreeMap::new();
        for (i, f) in all.iter().enumerate() {
            let r = root(&mut parent, i);
            comps.entry(r).or_default().0.frames.push(f.clone());
        }
        for e in &self.edges {
            let (a, c) = (e.from.to_string(), e.to.to_string());
            let r = root(&mut parent, index(&a));
            let (_, pairs) = comps.entry(r).or_default();
            // One entry per pair of frames, in the direction first seen.
            let key = if pairs.contains_key(&(c.clone(), a.clone())) {
                (c, a)
            } else {
                (a, c)
            };
            pairs.entry(key).or_default().push(e.name.clone());
        }
        for (a, name) in &self.quantities {
            let r = root(&mut parent, index(a));
            let (comp, _) = comps.entry(r).or_default();
            comp.quantities
                .entry(a.clone())
                .or_default()
                .push(name.clone());
        }
        comps
            .into_values()
            .map(|(mut comp, pairs)| {
                comp.edges = chain_order(&comp.frames, pairs);
                comp
            })
            .collect()
    }
}

/// The frame pairs of a component in the order a walk from its root meets
/// them: the root is the first frame that is never an inner frame (the
/// space frame {s} of T_sb, T_sc), so chains read from the outside in.
fn chain_order(frames: &[String], pairs: Pairs) -> Vec<((String, String), Vec<String>)> {
    let inner: Vec<&String> = pairs.keys().map(|(_, c)| c).collect();
    let root = frames
        .iter()
        .find(|f| !inner.contains(f))
        .or(frames.first());
    let mut depth: BTreeMap<&str, usize> = BTreeMap::new();
    let mut queue: VecDeque<&str> = root.map(String::as_str).into_iter().collect();
    if let Some(r) = root {
        depth.insert(r, 0);
    }
    while let Some(f) = queue.pop_front() {
        let d = depth[f];
        for (a, c) in pairs.keys() {
            let next = if a == f {
                c
            } else if c == f {
                a
            } else {
                continue;
            };
            if !depth.contains_key(next.as_str()) {
                depth.insert(next, d + 1);
                queue.push_back(next);
            }
        }
    }
    let at = |f: &String| depth.get(f.as_str()).copied().unwrap_or(usize::MAX);
    let mut keys: Vec<(String, String)> = pairs.keys().cloned().collect();
    keys.sort_by_key(|(a, c)| at(a).min(at(c)));
    drop(depth);
    let mut pairs = pairs;
    keys.into_iter()
        .map(|k| {
            let names = pairs.remove(&k).unwrap_or_default();
            (k, names)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::eval::env::Mode;
    use crate::session::Session;

    #[test]
    fn one_graph_for_derive_and_frames() {
        let mut s = Session::default();
        let src = "T_sb = Trans((1, 0, 0)); T_bc = RpToTrans(Rotz(1), (0, 0, 0)); p_c = (1, 2, 3); T_xy = eye(4); ans = T_sb";
        let (_, err, n) = s.run_to_strings("t", src, Mode::Run, false);
        assert_eq!(n, 0, "{err}");
        let g = FrameGraph::of(&s.env);
        let names: Vec<&str> = g.edges.iter().map(|e| e.name.as_str()).collect();
        assert_eq!(names, ["T_bc", "T_sb", "T_xy"]);
        assert_eq!(g.edges[0].kind, Kind::SE3);
        assert_eq!(g.quantities, [("c".to_string(), "p_c".to_string())]);
        let comps = g.components();
        assert_eq!(comps.len(), 2);
        assert_eq!(comps[0].frames, ["b", "c", "s"]);
        // From the outermost frame {s} inwards.
        let pairs: Vec<_> = comps[0].edges.iter().map(|(k, _)| k.clone()).collect();
        assert_eq!(
            pairs,
            [("s".into(), "b".into()), ("b".into(), "c".into())] as [(String, String); 2]
        );
        assert_eq!(comps[1].frames, ["x", "y"]);
    }
}
