//! Generators of Yin sets biased to degeneracy, for proptest and quickcheck, and the measured
//! statistics that show the degenerate cases really occur.
//!
//! A [`Shape`] is a short program on a small integer grid (coordinates 0..=6, shifted by at most
//! one): starting from 0̂, each [`Step`] joins or subtracts a primitive (the first step joins),
//! and the result may be complemented (unbounded sets, 1̂). The primitives are rectangles,
//! half-rectangles cut by a diagonal, diamonds (all edges slanted), general lattice triangles
//! (crossings at non-integer rational points), 3×3 blocks of unit cells traced by the
//! independent cell oracle (several components, corner contacts, a hole), and frames given
//! directly by their curves (a hole; an island inside a hole; an island touching its hole at
//! four points; a hole touching the outer curve, seed 000 Fig. 1). Because the grid is tiny,
//! independently drawn primitives share vertices, overlap along collinear edges and touch at
//! points all the time. Every intermediate result of a program must pass the validator.
//!
//! Pairs and triples are biased further: the second (third) shape is often *derived* from the
//! first by keeping some of its steps (coincident curves, equal orientation), swapping join and
//! subtract or complementing the whole program (coincident curves, opposite orientation),
//! shifting by one unit (collinear partial overlaps, touching corners) and adding steps.
//! Shrinking works on the programs: fewer steps, smaller primitives, no complement.

use super::cells::{Cells, Complex};
use super::runner::{qc_bool, qc_range, Program, Shares};
use super::Y;
use proptest::prelude::*;
use quickcheck::{Arbitrary, Gen};
use std::collections::HashSet;
use yinset::kernel::{classify, Contact, Point};
use yinset::num::Rational;
use yinset::yin2::YinSet2;

/// The largest coordinate of a primitive's vertex.
pub const GRID: i64 = 6;

/// A primitive region with vertices on the integer grid.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Prim {
    /// The rectangle [x, x+w] × [y, y+h].
    Rect { x: i64, y: i64, w: i64, h: i64 },
    /// The rectangle [x, x+w] × [y, y+h] cut by a diagonal: the three corners other than
    /// corner `drop` (0..4 counterclockwise from lower left).
    Half {
        x: i64,
        y: i64,
        w: i64,
        h: i64,
        drop: u8,
    },
    /// The square rotated by 45° with centre (x, y) and radius r.
    Diamond { x: i64, y: i64, r: i64 },
    /// A lattice triangle (made non-degenerate and counterclockwise when built).
    Tri {
        a: (i64, i64),
        b: (i64, i64),
        c: (i64, i64),
    },
    /// The union of the unit cells (x+i, y+j), i, j < 3, whose bit 3j+i is set in `mask`.
    Cells { x: i64, y: i64, mask: u16 },
    /// A square frame at (x, y), given directly by its curves: `kind` 0, the 3×3 square with
    /// a unit hole; 1, the 5×5 square with a 3×3 hole and a unit island in it; 2, the 4×4
    /// square with a 2×2 hole and a diamond island touching the hole at its four edge
    /// midpoints; 3, the 4×4 square with a triangular hole touching the outer curve at one
    /// point (seed 000 Fig. 1).
    Frame { x: i64, y: i64, kind: u8 },
}

/// Join (`add`) or subtract a primitive.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Step {
    pub add: bool,
    pub prim: Prim,
}

/// A Yin set as a program: fold the steps from 0̂, then complement if asked.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Shape {
    pub steps: Vec<Step>,
    pub complement: bool,
}

/// How a second shape is derived from a first one.
#[derive(Clone, Debug)]
pub struct Derive {
    /// Steps of the first shape kept (index modulo its length), and whether join and subtract
    /// are swapped.
    pub keep: Vec<(usize, bool)>,
    /// Translation of the kept steps (−1..=1 in each coordinate).
    pub shift: (i64, i64),
    /// Further steps.
    pub extra: Vec<Step>,
    pub complement: bool,
}

fn pt(x: i64, y: i64) -> Point<Rational> {
    Point::int(x, y)
}

fn rev(mut v: Vec<(i64, i64)>) -> Vec<(i64, i64)> {
    v.reverse();
    v
}

fn from_ring(v: Vec<(i64, i64)>) -> Y {
    YinSet2::from_curves(vec![v.into_iter().map(|(x, y)| pt(x, y)).collect()])
        .unwrap_or_else(|e| panic!("generator built an invalid primitive: {e}"))
}

impl Prim {
    /// The primitive's Yin set (one curve, or the cell oracle's curves for `Cells`).
    pub fn yin(&self) -> Y {
        match *self {
            Prim::Rect { x, y, w, h } => {
                from_ring(vec![(x, y), (x + w, y), (x + w, y + h), (x, y + h)])
            }
            Prim::Half { x, y, w, h, drop } => {
                let mut c = vec![(x, y), (x + w, y), (x + w, y + h), (x, y + h)];
                c.remove(drop as usize % 4);
                from_ring(c)
            }
            Prim::Diamond { x, y, r } => {
                from_ring(vec![(x, y - r), (x + r, y), (x, y + r), (x - r, y)])
            }
            Prim::Tri { a, b, c } => {
                let (a, b, c) = fix_triangle(a, b, c);
                from_ring(vec![a, b, c])
            }
            Prim::Frame { x, y, kind } => {
                let sq = |a: i64, b: i64, c: i64, d: i64| vec![(a, b), (c, b), (c, d), (a, d)];
                let mut curves = match kind % 4 {
                    0 => vec![sq(0, 0, 3, 3), rev(sq(1, 1, 2, 2))],
                    1 => vec![sq(0, 0, 5, 5), rev(sq(1, 1, 4, 4)), sq(2, 2, 3, 3)],
                    2 => vec![
                        sq(0, 0, 4, 4),
                        rev(sq(1, 1, 3, 3)),
                        vec![(2, 1), (3, 2), (2, 3), (1, 2)],
                    ],
                    _ => vec![sq(0, 0, 4, 4), vec![(2, 0), (1, 2), (3, 2)]],
                };
                for c in &mut curves {
                    for p in c.iter_mut() {
                        *p = (p.0 + x, p.1 + y);
                    }
                }
                YinSet2::from_curves(
                    curves
                        .into_iter()
                        .map(|c| c.into_iter().map(|(x, y)| pt(x, y)).collect())
                        .collect(),
                )
                .unwrap_or_else(|e| panic!("generator built an invalid frame: {e}"))
            }
            Prim::Cells { x, y, mask } => {
                let cx = Complex::grid(3, 3);
                let (dx, dy) = (
                    Rational::from_integer(x.into()),
                    Rational::from_integer(y.into()),
                );
                cx.yin_mapped(Cells::new(mask as u64 & 511, false), &|p| {
                    Point::new(p.x + dx.clone(), p.y + dy.clone())
                })
            }
        }
    }

    /// The same primitive translated by (dx, dy).
    pub fn shifted(&self, dx: i64, dy: i64) -> Prim {
        match self.clone() {
            Prim::Rect { x, y, w, h } => Prim::Rect {
                x: x + dx,
                y: y + dy,
                w,
                h,
            },
            Prim::Half { x, y, w, h, drop } => Prim::Half {
                x: x + dx,
                y: y + dy,
                w,
                h,
                drop,
            },
            Prim::Diamond { x, y, r } => Prim::Diamond {
                x: x + dx,
                y: y + dy,
                r,
            },
            Prim::Tri { a, b, c } => {
                let s = |p: (i64, i64)| (p.0 + dx, p.1 + dy);
                Prim::Tri {
                    a: s(a),
                    b: s(b),
                    c: s(c),
                }
            }
            Prim::Cells { x, y, mask } => Prim::Cells {
                x: x + dx,
                y: y + dy,
                mask,
            },
            Prim::Frame { x, y, kind } => Prim::Frame {
                x: x + dx,
                y: y + dy,
                kind,
            },
        }
    }

    /// Smaller variants, for quickcheck's shrinking.
    fn shrink_prim(&self) -> Vec<Prim> {
        let mut v = Vec::new();
        match *self {
            Prim::Rect { x, y, w, h } => {
                if x > 0 {
                    v.push(Prim::Rect { x: x - 1, y, w, h });
                }
                if y > 0 {
                    v.push(Prim::Rect { x, y: y - 1, w, h });
                }
                if w > 1 {
                    v.push(Prim::Rect { x, y, w: w - 1, h });
                }
                if h > 1 {
                    v.push(Prim::Rect { x, y, w, h: h - 1 });
                }
            }
            Prim::Half { x, y, w, h, drop } => {
                v.push(Prim::Rect { x, y, w, h });
                if x > 0 {
                    v.push(Prim::Half {
                        x: x - 1,
                        y,
                        w,
                        h,
                        drop,
                    });
                }
                if y > 0 {
                    v.push(Prim::Half {
                        x,
                        y: y - 1,
                        w,
                        h,
                        drop,
                    });
                }
                if w > 1 {
                    v.push(Prim::Half {
                        x,
                        y,
                        w: w - 1,
                        h,
                        drop,
                    });
                }
                if h > 1 {
                    v.push(Prim::Half {
                        x,
                        y,
                        w,
                        h: h - 1,
                        drop,
                    });
                }
            }
            Prim::Diamond { x, y, r } => {
                if r > 1 {
                    v.push(Prim::Diamond { x, y, r: r - 1 });
                }
                if x > r {
                    v.push(Prim::Diamond { x: x - 1, y, r });
                }
                if y > r {
                    v.push(Prim::Diamond { x, y: y - 1, r });
                }
            }
            Prim::Tri { a, b, c } => {
                v.push(Prim::Half {
                    x: 0,
                    y: 0,
                    w: 1,
                    h: 1,
                    drop: 2,
                });
                for (k, p) in [a, b, c].into_iter().enumerate() {
                    for q in [(p.0 - 1, p.1), (p.0, p.1 - 1)] {
                        if q.0 >= 0 && q.1 >= 0 {
                            let mut t = [a, b, c];
                            t[k] = q;
                            v.push(Prim::Tri {
                                a: t[0],
                                b: t[1],
                                c: t[2],
                            });
                        }
                    }
                }
            }
            Prim::Frame { x, y, kind } => {
                v.push(Prim::Rect { x, y, w: 1, h: 1 });
                if kind % 4 != 0 {
                    v.push(Prim::Frame { x, y, kind: 0 });
                }
                if x > 0 {
                    v.push(Prim::Frame { x: x - 1, y, kind });
                }
                if y > 0 {
                    v.push(Prim::Frame { x, y: y - 1, kind });
                }
            }
            Prim::Cells { x, y, mask } => {
                if x > 0 {
                    v.push(Prim::Cells { x: x - 1, y, mask });
                }
                if y > 0 {
                    v.push(Prim::Cells { x, y: y - 1, mask });
                }
                for b in 0..9 {
                    if mask >> b & 1 == 1 && mask & !(1 << b) != 0 {
                        v.push(Prim::Cells {
                            x,
                            y,
                            mask: mask & !(1 << b),
                        });
                    }
                }
            }
        }
        v
    }
}

/// A non-degenerate counterclockwise triangle from three lattice points.
fn fix_triangle(
    a: (i64, i64),
    mut b: (i64, i64),
    mut c: (i64, i64),
) -> ((i64, i64), (i64, i64), (i64, i64)) {
    if a == b {
        b.0 += 1;
    }
    let cross =
        |b: (i64, i64), c: (i64, i64)| (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0);
    if cross(b, c) == 0 {
        if a.0 == b.0 {
            c.0 += 1;
        } else {
            c.1 += 1;
        }
    }
    if cross(b, c) < 0 {
        (a, c, b)
    } else {
        (a, b, c)
    }
}

impl Shape {
    /// The Yin set of the program, computed with the kernel's join and difference; every
    /// intermediate result must pass the exact validator.
    pub fn build(&self) -> Y {
        let mut acc: Y = YinSet2::empty();
        for s in &self.steps {
            let p = s.prim.yin();
            acc = if s.add {
                acc.join(&p)
            } else {
                acc.difference(&p)
            };
            if let Err(e) = acc.validate() {
                panic!("building {self:?}: the validator rejects an intermediate result: {e}");
            }
        }
        if self.complement {
            acc.complement()
        } else {
            acc
        }
    }

    /// The second shape of a derived pair.
    pub fn derive(&self, d: &Derive) -> Shape {
        let mut steps = Vec::new();
        if !self.steps.is_empty() {
            for &(k, flip) in &d.keep {
                let s = &self.steps[k % self.steps.len()];
                steps.push(Step {
                    add: s.add != flip,
                    prim: s.prim.shifted(d.shift.0, d.shift.1),
                });
            }
        }
        steps.extend(d.extra.iter().cloned());
        Shape {
            steps,
            complement: d.complement,
        }
    }

    /// Smaller programs, for quickcheck's shrinking.
    pub fn shrink_shape(&self) -> Vec<Shape> {
        let mut v = Vec::new();
        if self.complement {
            v.push(Shape {
                steps: self.steps.clone(),
                complement: false,
            });
        }
        for k in 0..self.steps.len() {
            let mut s = self.clone();
            s.steps.remove(k);
            v.push(s);
        }
        for k in 0..self.steps.len() {
            if !self.steps[k].add {
                let mut s = self.clone();
                s.steps[k].add = true;
                v.push(s);
            }
            for p in self.steps[k].prim.shrink_prim() {
                let mut s = self.clone();
                s.steps[k].prim = p;
                v.push(s);
            }
        }
        v
    }
}

// ---------------------------------------------------------------------------------------------
// proptest strategies

pub mod strategies {
    use super::*;

    pub fn prim() -> impl Strategy<Value = Prim> {
        let c = 0..=GRID;
        prop_oneof![
            3 => (0..GRID, 0..GRID, 1..=3i64, 1..=3i64)
                .prop_map(|(x, y, w, h)| Prim::Rect { x, y, w, h }),
            2 => (0..GRID, 0..GRID, 1..=3i64, 1..=3i64, 0..4u8)
                .prop_map(|(x, y, w, h, drop)| Prim::Half { x, y, w, h, drop }),
            1 => (1..GRID, 1..GRID, 1..=2i64).prop_map(|(x, y, r)| Prim::Diamond { x, y, r }),
            1 => ((c.clone(), c.clone()), (c.clone(), c.clone()), (c.clone(), c))
                .prop_map(|(a, b, c)| Prim::Tri { a, b, c }),
            2 => (0..=3i64, 0..=3i64, 1..512u16).prop_map(|(x, y, mask)| Prim::Cells { x, y, mask }),
            1 => (0..=2i64, 0..=2i64, 0..4u8).prop_map(|(x, y, kind)| Prim::Frame { x, y, kind }),
        ]
    }

    pub fn step() -> impl Strategy<Value = Step> {
        (proptest::bool::weighted(0.7), prim()).prop_map(|(add, prim)| Step { add, prim })
    }

    pub fn shape() -> impl Strategy<Value = Shape> {
        (
            proptest::collection::vec(step(), 1..=4),
            proptest::bool::weighted(0.25),
        )
            .prop_map(|(mut steps, complement)| {
                steps[0].add = true; // a program starting with a subtraction is wasted
                Shape { steps, complement }
            })
    }

    pub fn derive() -> impl Strategy<Value = Derive> {
        (
            proptest::collection::vec((0..4usize, proptest::bool::weighted(0.3)), 1..=3),
            prop_oneof![3 => Just((0i64, 0i64)), 2 => (-1..=1i64, -1..=1i64)],
            proptest::collection::vec(step(), 0..=1),
            proptest::bool::weighted(0.25),
        )
            .prop_map(|(keep, shift, extra, complement)| Derive {
                keep,
                shift,
                extra,
                complement,
            })
    }

    /// A shape related to `a` about two thirds of the time: derived from it, or its
    /// complement program (every curve reversed).
    fn related(a: Shape) -> impl Strategy<Value = Shape> {
        let flipped = Shape {
            steps: a.steps.clone(),
            complement: !a.complement,
        };
        prop_oneof![
            2 => shape(),
            3 => derive().prop_map(move |d| a.derive(&d)),
            1 => Just(flipped),
        ]
    }

    pub fn pair() -> impl Strategy<Value = (Shape, Shape)> {
        shape().prop_flat_map(|a| (Just(a.clone()), related(a)))
    }

    pub fn triple() -> impl Strategy<Value = (Shape, Shape, Shape)> {
        shape().prop_flat_map(|a| (Just(a.clone()), related(a.clone()), related(a)))
    }
}

// ---------------------------------------------------------------------------------------------
// quickcheck: Arbitrary + shrink

impl Arbitrary for Prim {
    fn arbitrary(g: &mut Gen) -> Prim {
        let r = |g: &mut Gen, lo, hi| qc_range(g, lo, hi);
        match r(g, 0, 9) {
            0..=2 => Prim::Rect {
                x: r(g, 0, GRID - 1),
                y: r(g, 0, GRID - 1),
                w: r(g, 1, 3),
                h: r(g, 1, 3),
            },
            3..=4 => Prim::Half {
                x: r(g, 0, GRID - 1),
                y: r(g, 0, GRID - 1),
                w: r(g, 1, 3),
                h: r(g, 1, 3),
                drop: r(g, 0, 3) as u8,
            },
            5 => Prim::Diamond {
                x: r(g, 1, GRID - 1),
                y: r(g, 1, GRID - 1),
                r: r(g, 1, 2),
            },
            6 => Prim::Tri {
                a: (r(g, 0, GRID), r(g, 0, GRID)),
                b: (r(g, 0, GRID), r(g, 0, GRID)),
                c: (r(g, 0, GRID), r(g, 0, GRID)),
            },
            7..=8 => Prim::Cells {
                x: r(g, 0, 3),
                y: r(g, 0, 3),
                mask: r(g, 1, 511) as u16,
            },
            _ => Prim::Frame {
                x: r(g, 0, 2),
                y: r(g, 0, 2),
                kind: r(g, 0, 3) as u8,
            },
        }
    }

    fn shrink(&self) -> Box<dyn Iterator<Item = Prim>> {
        Box::new(self.shrink_prim().into_iter())
    }
}

impl Arbitrary for Step {
    fn arbitrary(g: &mut Gen) -> Step {
        Step {
            add: qc_bool(g, 0.7),
            prim: Prim::arbitrary(g),
        }
    }
}

impl Arbitrary for Shape {
    fn arbitrary(g: &mut Gen) -> Shape {
        let n = qc_range(g, 1, 4) as usize;
        let mut steps: Vec<Step> = (0..n).map(|_| Step::arbitrary(g)).collect();
        steps[0].add = true;
        Shape {
            steps,
            complement: qc_bool(g, 0.25),
        }
    }

    fn shrink(&self) -> Box<dyn Iterator<Item = Shape>> {
        Box::new(self.shrink_shape().into_iter())
    }
}

/// A shape related to `a` (derived from it most of the time), for quickcheck's pairs.
fn qc_related(g: &mut Gen, a: &Shape) -> Shape {
    match qc_range(g, 0, 5) {
        0..=1 => return Shape::arbitrary(g),
        2 => {
            return Shape {
                steps: a.steps.clone(),
                complement: !a.complement,
            }
        }
        _ => {}
    }
    let k = qc_range(g, 1, 3) as usize;
    let shift = if qc_bool(g, 0.6) {
        (0, 0)
    } else {
        (qc_range(g, -1, 1), qc_range(g, -1, 1))
    };
    let d = Derive {
        keep: (0..k)
            .map(|_| (qc_range(g, 0, 3) as usize, qc_bool(g, 0.3)))
            .collect(),
        shift,
        extra: if qc_bool(g, 0.5) {
            vec![Step::arbitrary(g)]
        } else {
            vec![]
        },
        complement: qc_bool(g, 0.25),
    };
    a.derive(&d)
}

impl Program for Shape {
    fn related(g: &mut Gen, a: &Shape) -> Shape {
        qc_related(g, a)
    }
    fn smaller(&self) -> Vec<Shape> {
        self.shrink_shape()
    }
}

// ---------------------------------------------------------------------------------------------
// Degenerate-case statistics

/// Which degenerate features a generated pair (A, B) shows.
#[derive(Clone, Debug, Default)]
pub struct Features {
    /// A vertex of ∂A is a vertex of ∂B.
    pub shared_vertex: bool,
    /// An edge of ∂A and an edge of ∂B overlap along a stretch of positive length.
    pub collinear_overlap: bool,
    /// ∂A and ∂B meet at a point that is an endpoint of an edge and lies on no shared stretch
    /// and no proper crossing (a vertex touching the other boundary).
    pub touching_point: bool,
    /// Two curves of A or of B touch each other at a point (an improper intersection).
    pub touching_curves: bool,
    /// A curve of A equals a curve of B (same orientation).
    pub coincident_same: bool,
    /// A curve of A is the reverse of a curve of B.
    pub coincident_opposite: bool,
    /// A or B has a hole.
    pub holes: bool,
    /// A or B has at least two components.
    pub several_components: bool,
    /// A or B has a positive curve inside a negative one (an island in a hole).
    pub island_in_hole: bool,
    /// A or B is unbounded (1̂ included).
    pub unbounded: bool,
    /// A or B is 0̂ or 1̂.
    pub trivial: bool,
    /// A or B has a slanted edge.
    pub slanted: bool,
}

/// What [`Features::as_array`] reports, in order.
pub const FEATURE_NAMES: [&str; 12] = [
    "shared vertex",
    "collinear overlapping edges",
    "∂A, ∂B meet at an isolated vertex contact",
    "curves of one set touching at a point",
    "coincident curves, equal orientation",
    "coincident curves, opposite orientation",
    "holes",
    "several components",
    "island inside a hole",
    "unbounded",
    "0̂ or 1̂",
    "slanted edges",
];

impl Features {
    pub fn as_array(&self) -> [bool; 12] {
        [
            self.shared_vertex,
            self.collinear_overlap,
            self.touching_point,
            self.touching_curves,
            self.coincident_same,
            self.coincident_opposite,
            self.holes,
            self.several_components,
            self.island_in_hole,
            self.unbounded,
            self.trivial,
            self.slanted,
        ]
    }

    /// Measure the features of a pair (computed from the curves, exactly).
    pub fn of(a: &Y, b: &Y) -> Features {
        let mut f = Features::default();
        let verts = |y: &Y| -> HashSet<Point<Rational>> {
            y.curves()
                .iter()
                .flat_map(|c| c.vertices().iter().cloned())
                .collect()
        };
        f.shared_vertex = !verts(a).is_disjoint(&verts(b));
        let edges = |y: &Y| -> Vec<(Point<Rational>, Point<Rational>)> {
            y.curves()
                .iter()
                .flat_map(|c| c.edges().map(|(p, q)| (p.clone(), q.clone())))
                .collect()
        };
        let (ea, eb) = (edges(a), edges(b));
        let mut touch = HashSet::new();
        let mut excluded = HashSet::new();
        let mut overlaps: Vec<(Point<Rational>, Point<Rational>)> = Vec::new();
        for (p, q) in &ea {
            for (r, s) in &eb {
                match classify(p, q, r, s, &()) {
                    Contact::Overlap(u, v) => {
                        f.collinear_overlap = true;
                        overlaps.push((u, v));
                    }
                    Contact::Touching(u) => {
                        touch.insert(u);
                    }
                    Contact::Crossing(u) => {
                        excluded.insert(u);
                    }
                    Contact::Disjoint => {}
                }
            }
        }
        f.touching_point = touch.iter().any(|t| {
            !excluded.contains(t)
                && !overlaps.iter().any(|(u, v)| {
                    yinset::kernel::orient(u, v, t, &()) == std::cmp::Ordering::Equal
                        && yinset::kernel::on_closed_segment(u, v, t)
                })
        });
        let self_touch = |y: &Y| {
            let mut seen = HashSet::new();
            y.curves().iter().any(|c| {
                let vs: HashSet<&Point<Rational>> = c.vertices().iter().collect();
                vs.into_iter().any(|v| !seen.insert(v.clone()))
            })
        };
        f.touching_curves = self_touch(a) || self_touch(b);
        let ca: HashSet<_> = a.curves().iter().collect();
        f.coincident_same = b.curves().iter().any(|c| ca.contains(c));
        let rev: Vec<_> = b.curves().iter().map(|c| c.reversed()).collect();
        f.coincident_opposite = rev.iter().any(|c| ca.contains(c));
        for y in [a, b] {
            let bt = y.betti();
            f.holes |= bt.total_holes > 0;
            f.several_components |= bt.components > 1;
            let pos: Vec<bool> = y.curves().iter().map(|c| c.is_positive()).collect();
            f.island_in_hole |= y
                .parents()
                .iter()
                .enumerate()
                .any(|(i, p)| pos[i] && p.is_some_and(|p| !pos[p]));
            f.unbounded |= !y.is_bounded();
            f.trivial |= y.is_empty() || y.is_full();
            f.slanted |= y
                .curves()
                .iter()
                .any(|c| c.edges().any(|(p, q)| p.x != q.x && p.y != q.y));
        }
        f
    }
}

/// The statistics of [`Features`] over a sample of pairs, asserted on any sample.
pub const fn feature_stats() -> Shares<12> {
    Shares::new(&FEATURE_NAMES, 0)
}
