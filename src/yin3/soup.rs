//! The triangles of an arrangement over one table of interned points (seed 004 steps 1–2: the
//! operands' triangles, then the contact points they gain).

use super::set::Brep;
use crate::kernel::Point3;
use crate::num::Num;
use foldhash::HashMap;

/// Triangles over one table of interned points, each tagged with its operand.
#[derive(Clone, Debug, Default)]
pub(crate) struct Soup<N: Num> {
    /// The points; equal points have one index.
    pub points: Vec<Point3<N>>,
    /// Each point's index; `None` until the first [`Soup::intern`] of a soup made from
    /// distinct points ([`Soup::of_distinct`]).
    index: Option<HashMap<Point3<N>, usize>>,
    /// The triangles, as indices into `points`.
    pub tris: Vec<[usize; 3]>,
    /// The operand (0 or 1) of each triangle.
    pub operand: Vec<u8>,
}

impl<N: Num> Soup<N> {
    /// An empty soup.
    pub(crate) fn new() -> Soup<N> {
        Soup {
            points: Vec::new(),
            index: Some(HashMap::default()),
            tris: Vec::new(),
            operand: Vec::new(),
        }
    }

    /// A soup of the pairwise distinct `points` and no triangles yet.
    pub(crate) fn of_distinct(points: Vec<Point3<N>>) -> Soup<N> {
        Soup {
            points,
            index: None,
            tris: Vec::new(),
            operand: Vec::new(),
        }
    }

    /// The index of `p`, added if new.
    pub(crate) fn intern(&mut self, p: &Point3<N>) -> usize {
        let points = &mut self.points;
        let index = (self.index).get_or_insert_with(|| points.iter().cloned().zip(0..).collect());
        if let Some(&i) = index.get(p) {
            return i;
        }
        points.push(p.clone());
        index.insert(p.clone(), points.len() - 1);
        points.len() - 1
    }

    /// The soup of a meet's operands: the triangles of the boundary `a` (operand 0), then
    /// those of `b` (operand 1).
    pub(crate) fn of_operands(a: &Brep<N>, b: &Brep<N>) -> Soup<N> {
        let mut soup = Soup::new();
        for (operand, brep) in [a, b].into_iter().enumerate() {
            for t in 0..brep.tris.len() {
                soup.push(brep.corners(t), operand as u8);
            }
        }
        soup
    }

    /// Add the triangle `abc` of operand `operand`.
    pub(crate) fn push(&mut self, t: [&Point3<N>; 3], operand: u8) {
        let t = t.map(|p| self.intern(p));
        self.push_interned(t, operand);
    }

    /// Add the triangle of operand `operand` whose corners are the interned points `t`.
    pub(crate) fn push_interned(&mut self, t: [usize; 3], operand: u8) {
        self.tris.push(t);
        self.operand.push(operand);
    }

    /// The corners of triangle `i`.
    pub(crate) fn corners(&self, i: usize) -> [&Point3<N>; 3] {
        self.tris[i].map(|v| &self.points[v])
    }
}
