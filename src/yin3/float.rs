//! 3D float mode (yin3 docs: *Float mode*): float sets are exactly valid sets of their `f64`
//! values, and every decision about them is made on those values read as rationals. An
//! operation is computed exactly and the result's vertices are rounded to the nearest `f64`s;
//! the rounded boundary is accepted only if it is valid exactly and has the exact result's
//! topology ([`Topology`]), otherwise the operation fails with
//! [`Yin3Error::Unrepresentable`]. Operands that cross transversally, touch only in shared
//! corners and edges, or do not meet take the construction-light path of
//! [`super::transversal`], others the general exact arrangement; either way the meet's
//! triangles are rounded as they come, the exact boundary assembled only where its topology
//! must be computed.

use super::error::Yin3Error;
use super::fins::FinTable;
use super::kept::{provably_kept, Merges, Topology};
use super::meet::general_pieces;
use super::set::{compact, Brep, Repr3, YinSet3};
use super::transversal::{transversal_meet, Transversal};
use super::validate::{check_windings, conforming_after_moves, revalidate};
use super::values::{exact_point, exact_points};
use crate::kernel::Point3;
use crate::num::{Num, Rational};
use foldhash::{HashMap, HashMapExt};

/// The meet of two float sets, with the boundaries `x` and `y`, under the combined context
/// `ctx` (module docs): the transversal meet where it applies, else the general arrangement on
/// the values read as rationals; either way its triangles rounded.
pub(crate) fn float_meet<N: Num>(
    [a, b]: [&YinSet3<N>; 2],
    [x, y]: [&Brep<N>; 2],
    ctx: N::Ctx,
) -> Result<YinSet3<N>, Yin3Error> {
    let (points, kept) = match transversal_meet(x, y) {
        Some(Transversal::Operand(o)) => return Ok([a, b][o].clone().with_ctx(ctx)),
        Some(meet) => meet.complex(x, y),
        // A degenerate contact, which exact mode's transversal meet would find again on the
        // same values.
        None => general_pieces(&x.exact_values(), &y.exact_values()),
    };
    if kept.is_empty() {
        return Ok(YinSet3::empty().with_ctx(ctx));
    }
    let (points, kept) = compact(points, kept);
    let rounded = rounded_points(&points)?;
    let moved = moved(&rounded, &points);
    let exact = || Ok(Topology::of(&Brep::assemble(points.clone(), kept.clone())?));
    Ok(YinSet3::from_brep(
        rounded_complex(rounded, moved, &points, kept.clone(), None, exact)?,
        ctx,
    ))
}

/// `op` computed exactly on the operands' values and rounded once, under the context `ctx`.
pub(crate) fn rounded_exact<N: Num>(
    a: &YinSet3<N>,
    b: &YinSet3<N>,
    ctx: N::Ctx,
    op: impl Fn(&YinSet3<Rational>, &YinSet3<Rational>) -> YinSet3<Rational>,
) -> Result<YinSet3<N>, Yin3Error> {
    rounded_set(op(&a.exact_values(), &b.exact_values()), ctx)
}

/// The error that a rounded result is not valid.
fn unrepresentable(e: &dyn std::fmt::Display) -> Yin3Error {
    Yin3Error::Unrepresentable(e.to_string())
}

/// The exact boundary `b` with every vertex rounded to the nearest `f64`. If none moved, the
/// exact structure is kept as it is; otherwise as [`rounded_complex`].
pub(crate) fn rounded_brep<N: Num>(b: Brep<Rational>) -> Result<Brep<N>, Yin3Error> {
    let rounded = rounded_points::<N>(&b.points)?;
    let moved = moved(&rounded, &b.points);
    if moved.iter().all(Option::is_none) {
        // Distinct exact points, each an f64 already: the same boundary, no work to redo.
        return Ok(b.with_points(rounded));
    }
    rounded_complex(
        rounded,
        moved,
        &b.points,
        b.tris.clone(),
        Some(&b.table),
        || Ok(Topology::of(&b)),
    )
}

/// For each exact point, the exact value of its rounding in `rounded` where that differs from
/// it (where it moved: where it is no `f64`, whose nearest `f64` is itself).
fn moved<N: Num>(
    rounded: &[Point3<N>],
    exact: &[Point3<Rational>],
) -> Vec<Option<Point3<Rational>>> {
    rounded
        .iter()
        .zip(exact)
        .map(|(q, p)| (!p.is_f64()).then(|| exact_point(q)))
        .collect()
}

/// The nearest `f64` point.
fn rounded_point<N: Num>(p: &Point3<Rational>) -> Result<Point3<N>, Yin3Error> {
    let f = |v: &Rational| N::from_f64(v.to_f64()).map_err(|e| unrepresentable(&e));
    Ok(Point3::new(f(&p.x)?, f(&p.y)?, f(&p.z)?))
}

/// The nearest `f64` points.
fn rounded_points<N: Num>(points: &[Point3<Rational>]) -> Result<Vec<Point3<N>>, Yin3Error> {
    points.iter().map(rounded_point).collect()
}

/// The boundary of a valid set — the triangles `tris` over the exact points `exact`, compact
/// and conforming, as the validator would rebuild it — with each point replaced by its rounding
/// in `rounded` (`moved`: its exact value where it differs; `exact_table`: the exact
/// boundary's fin table where it was built). If none moved, it is the exact
/// boundary. Vertices that round to one point are merged, and triangles that collapse to a
/// segment or a point dropped (each takes a pair of opposite fins off an edge, so closed
/// surfaces stay closed). Then only the triangles at moved points are checked against their
/// neighbours ([`conforming_after_moves`]); where that cannot show the boundary conforming,
/// it is validated in full. The result must have the exact one's topology, computed by `keep`
/// unless [`provably_kept`] shows it (which also shows the windings of a conforming boundary
/// with the exact triangles, or with those after merges it shows to be edge collapses that
/// keep each surface's type, I4: see [`Shown::Conforming`]). Any failure is
/// [`Yin3Error::Unrepresentable`].
fn rounded_complex<N: Num>(
    rounded: Vec<Point3<N>>,
    moved: Vec<Option<Point3<Rational>>>,
    exact: &[Point3<Rational>],
    tris: Vec<[usize; 3]>,
    exact_table: Option<&FinTable>,
    keep: impl FnOnce() -> Result<Topology, Yin3Error>,
) -> Result<Brep<N>, Yin3Error> {
    if moved.iter().all(Option::is_none) {
        // Every point an `f64` already: the exact boundary itself, valid, with its topology.
        return Brep::assemble(rounded, tris).map_err(|e| unrepresentable(&e));
    }
    let (brep, shown, merges) = rounded_boundary(rounded, moved, exact, tris)?;
    let same_triangles = matches!(
        shown,
        Shown::Conforming { same: true } | Shown::Valid { same: true }
    );
    let proven = match merges {
        _ if same_triangles => provably_kept(&brep, exact, exact_table, &Merges::none()),
        Some((merges, values)) => provably_kept(&brep, &values, None, &merges),
        None => false,
    };
    // The windings of a conforming boundary are shown where it is proven with two fins at
    // every edge ([`Shown::Conforming`]), and checked otherwise.
    let two_fins = || brep.table.fin_lists().all(|f| f.len() == 2);
    if matches!(shown, Shown::Conforming { .. }) && !(proven && two_fins()) {
        check_windings(&brep.exact_values(), &()).map_err(|e| unrepresentable(&e))?;
    }
    if proven {
        return Ok(brep);
    }
    let (keep, got) = (keep()?, Topology::of(&brep));
    if got != keep {
        return Err(unrepresentable(&format!(
            "rounding to f64 changes the topology of the result (exact: {keep}; rounded: {got})"
        )));
    }
    Ok(brep)
}

/// What [`rounded_boundary`] has shown of its boundary's validity.
enum Shown {
    /// Conforming (I1–I3): valid once its windings are (I4). `same` if it has the exact
    /// boundary's very triangles, numbering kept; where [`provably_kept`] also holds, of these
    /// triangles or of those after the merges it is given, and every edge has two fins, its
    /// windings are shown. With two fins per edge the glued surfaces are the edge-connected
    /// surfaces I4 speaks of; each is embedded and splits space in two, so its own winding
    /// number beside it is 0 on the side its normals point to if it is positive, −1 if
    /// negative, and it keeps its orientation and the winding number about it of every other
    /// surface. So the winding number beside each triangle is the exact boundary's, which is
    /// valid; and the rounded boundedness, recomputed from the rounded volumes, is the exact
    /// one (the volume is the integral of the winding number).
    Conforming { same: bool },
    /// Validated in full; `same` as for `Conforming`.
    Valid { same: bool },
}

/// What [`rounded_boundary`] shows of the vertices it merged, for [`provably_kept`]: the
/// merges ([`Merges::of`]) and the exact value of each rounded vertex.
type Merged = Option<(Merges, Vec<Point3<Rational>>)>;

/// The rounded boundary of [`rounded_complex`], before its topology is compared, how far it is
/// shown valid, and where vertices merged, what is shown of the merges.
fn rounded_boundary<N: Num>(
    rounded: Vec<Point3<N>>,
    moved: Vec<Option<Point3<Rational>>>,
    exact: &[Point3<Rational>],
    tris: Vec<[usize; 3]>,
) -> Result<(Brep<N>, Shown, Merged), Yin3Error> {
    // Each rounded point's first index among equal ones: itself unless rounding merged it.
    let (rep, distinct) = {
        let mut first: HashMap<&Point3<N>, usize> = HashMap::with_capacity(rounded.len());
        let rep: Vec<usize> = (rounded.iter().enumerate())
            .map(|(i, q)| *first.entry(q).or_insert(i))
            .collect();
        (rep, first.len())
    };
    if distinct == rounded.len() {
        let flags: Vec<bool> = moved.iter().map(Option::is_some).collect();
        // The rounded points' exact values: those that did not move are the exact points.
        let values = (moved.into_iter().zip(exact))
            .map(|(m, p)| m.unwrap_or_else(|| p.clone()))
            .collect();
        let on_values =
            Brep::<Rational>::assemble(values, tris.clone()).map_err(|e| unrepresentable(&e))?;
        // Where assembly kept the triangles (`same`) it kept the numbering (it renumbers by
        // first use, the identity on a compact boundary), so `flags` and `rounded` still apply.
        let same = on_values.tris == tris;
        if same && conforming_after_moves(&rounded, &on_values.tris, &flags) {
            return Ok((
                on_values.with_points(rounded),
                Shown::Conforming { same: true },
                None,
            ));
        }
        let points: Vec<Point3<N>> = (on_values.points.iter())
            .map(|p| rounded_point(p).expect("the values of rounded points are f64s"))
            .collect();
        let values = on_values.points.clone();
        let brep = on_values.with_points(points);
        revalidate(values, &brep, ()).map_err(|e| unrepresentable(&e))?;
        return Ok((brep, Shown::Valid { same }, None));
    }
    // The triangles that do not collapse, over the merged points numbered by first use (so
    // that assembly keeps the numbering), and for each exact point its merged number.
    let mut to = vec![usize::MAX; rounded.len()];
    let mut order = Vec::new();
    let kept: Vec<[usize; 3]> = (tris.iter())
        .map(|t| t.map(|v| rep[v]))
        .filter(|[p, q, r]| p != q && q != r && r != p)
        .map(|t| {
            t.map(|v| {
                if to[v] == usize::MAX {
                    to[v] = order.len();
                    order.push(v);
                }
                to[v]
            })
        })
        .collect();
    if kept.is_empty() {
        return Err(unrepresentable(&"every triangle collapsed when rounded"));
    }
    // Each exact point's merged number, if a kept triangle uses it.
    let number = |v: usize| Some(to[rep[v]]).filter(|&i| i != usize::MAX);
    // The merged points that a moved point became: every triangle at one is checked.
    let mut flags = vec![false; order.len()];
    for v in (0..moved.len()).filter(|&v| moved[v].is_some()) {
        if let Some(i) = number(v) {
            flags[i] = true;
        }
    }
    let merged = ((0..rep.len()).map(number))
        .collect::<Option<Vec<usize>>>()
        .and_then(|to| Merges::of(order.len(), &tris, &to, exact));
    // Each merged point's exact value is its first exact point's rounding (`moved`, else that
    // point itself), which assembly reads instead of converting the rounded point again.
    let values = (order.iter())
        .map(|&v| moved[v].clone().unwrap_or_else(|| exact[v].clone()))
        .collect();
    let mut slots: Vec<Option<Point3<N>>> = rounded.into_iter().map(Some).collect();
    let points = (order.iter())
        .map(|&v| slots[v].take().expect("each merged point once"))
        .collect();
    let brep = (Brep::<Rational>::assemble(values, kept))
        .map_err(|e| unrepresentable(&e))?
        .with_points(points);
    // The triangles that are left met only in shared corners and edges before they moved, and
    // merging points gave a shared corner only to triangles at a moved point.
    if conforming_after_moves(&brep.points, &brep.tris, &flags) {
        return Ok((brep, Shown::Conforming { same: false }, merged));
    }
    revalidate(exact_points(&brep.points), &brep, ()).map_err(|e| unrepresentable(&e))?;
    Ok((brep, Shown::Valid { same: false }, merged))
}

/// The exact set `y` rounded ([`rounded_brep`]), under the context `ctx`.
fn rounded_set<N: Num>(y: YinSet3<Rational>, ctx: N::Ctx) -> Result<YinSet3<N>, Yin3Error> {
    Ok(match y.repr {
        Repr3::Brep(b) => YinSet3::from_brep(rounded_brep(*b)?, ctx),
        Repr3::Empty => YinSet3::empty().with_ctx(ctx),
        Repr3::Full => YinSet3::full().with_ctx(ctx),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Float;
    use crate::yin3::kept::SPLIT_TETRAHEDRON;

    /// A tetrahedron whose edge AB carries a vertex M a third of 2⁻⁶⁰ from A, splitting its two
    /// faces at AB: M rounds to A, the two triangles at AM collapse, and the rounded boundary
    /// is the tetrahedron, shown conforming by the triangles at the merged point alone.
    #[test]
    fn a_point_rounding_onto_another_merges_and_is_checked_locally() {
        let (exact, tris) = split_tetrahedron();
        Brep::assemble(exact.clone(), tris.clone()).expect("the exact boundary is valid");
        let rounded: Vec<Point3<Float>> = rounded_points(&exact).unwrap();
        assert_eq!(rounded[4], rounded[0]);
        let moved = moved(&rounded, &exact);
        let (brep, shown, merged) = rounded_boundary(rounded, moved, &exact, tris).unwrap();
        assert!(matches!(shown, Shown::Conforming { same: false }));
        assert!(merged.is_some());
        assert_eq!((brep.points.len(), brep.tris.len()), (4, 4));
    }

    /// The points and triangles of the tetrahedron above.
    fn split_tetrahedron() -> (Vec<Point3<Rational>>, Vec<[usize; 3]>) {
        let r = |n: i64| Rational::from_i64(n);
        let d = Rational::new(1.into(), (3 * (1i64 << 60)).into());
        let exact = vec![
            Point3::new(r(1), r(1), r(1)),
            Point3::new(r(2), r(1), r(1)),
            Point3::new(r(1), r(2), r(1)),
            Point3::new(r(1), r(1), r(2)),
            Point3::new(r(1) + d, r(1), r(1)),
        ];
        (exact, SPLIT_TETRAHEDRON.to_vec())
    }

    /// The merge above is an edge collapse that keeps the tetrahedron's topology, proven
    /// without computing the exact boundary's.
    #[test]
    fn a_merge_that_collapses_an_edge_is_proven_to_keep_the_topology() {
        let (exact, tris) = split_tetrahedron();
        let rounded: Vec<Point3<Float>> = rounded_points(&exact).unwrap();
        let moved = moved(&rounded, &exact);
        let keep = || -> Result<Topology, Yin3Error> { panic!("the exact topology was computed") };
        let brep = rounded_complex(rounded, moved, &exact, tris, None, keep).unwrap();
        assert_eq!((brep.points.len(), brep.tris.len()), (4, 4));
    }
}
