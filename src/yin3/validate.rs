//! Validation of user triangles ([`YinSet3::from_triangles`]) and the public validator
//! ([`YinSet3::validate`]) (yin3 docs: *Validation*): faces are checked and triangulated, legal
//! contacts (T-junctions, a vertex or an edge on a face) made conforming by the arrangement of
//! the faces against each other, and invariants I1–I4 checked, with errors naming the face or
//! edge at fault.

use super::arrange::{arrange, shared_only, ArrangeError, Pairs};
use super::error::{Spot, Yin3Error};
use super::geom::{collinear, normal, widened_box, Chart};
use super::grid::on_grid;
use super::locate::{ray_box, winding};
use super::parallel::PARALLEL_FROM;
use super::set::{Brep, YinSet3};
use super::soup::Soup;
use super::star::FlatStars;
use super::sweep::MeetingBoxes;
use super::tri::{apart, images_meet_only_in_shared, intersect, off_plane_but_shared, Image};
use super::triangulate::ear_clip;
use super::values::{exact_point, exact_points};
use crate::kernel::{orient, orient3d, BBox3, Point, Point3};
use crate::num::{Float, NearPlane, Num, PlaneF64};
use crate::union_find::UnionFind;
use foldhash::{HashSet, HashSetExt};
use rayon::prelude::*;
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{Envelope, RTree, AABB};
use smallvec::{smallvec, SmallVec};
use std::cmp::Ordering;
use std::sync::OnceLock;

impl<N: Num> YinSet3<N> {
    /// Check that the stored boundary is a valid boundary representation (I1–I4), as
    /// [`YinSet3::from_triangles`] would accept it unchanged; every operation's output passes.
    /// Float sets are checked exactly, on their `f64` values read as rationals.
    ///
    /// ```
    /// use yinset::{kernel::Point3, num::{Num, Rational}, yin3::YinSet3};
    /// let cube = |x: i64, y: i64, z: i64, s: i64| {
    ///     YinSet3::<Rational>::cuboid(&Point3::int(x, y, z), &Point3::int(x + s, y + s, z + s)).unwrap()
    /// };
    /// let (a, b) = (cube(0, 0, 0, 2), cube(1, 1, 1, 2));
    /// for r in [&a & &b, &a | &b, &a - &b, &a ^ &b, !&a] {
    ///     r.validate()?; // every operation's output is a valid boundary representation
    /// }
    /// # Ok::<(), yinset::yin3::Yin3Error>(())
    /// ```
    pub fn validate(&self) -> Result<(), Yin3Error> {
        let Some(b) = self.brep() else {
            return Ok(());
        };
        if N::EXACT {
            revalidate(b.points.clone(), b, self.ctx)
        } else {
            revalidate(exact_points(&b.points), b, ())
        }
    }
}

/// Rebuild the boundary `b` from its triangles over `points` (its vertices in backend `M`) and
/// compare: the same triangles, glued surfaces, Hasse diagram and boundedness.
pub(crate) fn revalidate<M: Num, N: Num>(
    points: Vec<Point3<M>>,
    b: &Brep<N>,
    ctx: M::Ctx,
) -> Result<(), Yin3Error> {
    let faces = b.tris.iter().map(|t| t.to_vec()).collect();
    let again = YinSet3::from_triangles_with(points, faces, ctx)?;
    let rebuilt = again.brep().expect("a non-empty boundary");
    if rebuilt.tris.len() != b.tris.len() {
        return Err(Yin3Error::Internal(format!(
            "the stored triangles are not conforming: validation re-cut {} triangles into {}",
            b.tris.len(),
            rebuilt.tris.len()
        )));
    }
    if rebuilt.surfaces != b.surfaces || rebuilt.parent != b.parent || rebuilt.bounded != b.bounded
    {
        return Err(Yin3Error::Internal(
            "the stored glued surfaces or Hasse diagram differ from the recomputed ones".into(),
        ));
    }
    Ok(())
}

/// True if the validator would rebuild the boundary of the triangles `tris` over `points`
/// unchanged (I4 aside), knowing that it did before the vertices `moved` moved (a rounded
/// result: where moved points were merged with others, the merged points are flagged and the
/// triangles that collapsed are gone, so every other triangle kept its corners and its
/// neighbours but for those): every triangle with a moved vertex meets every other
/// triangle exactly in their shared vertices and edges (a degenerate one fails against its
/// neighbours across its edges). Decided by exact orientations of the points' values — first
/// for all pairs of a flat star at once ([`FlatStars`]), then by either triangle's plane where
/// a filter is certain ([`off_plane_but_shared`]), then on images in a coordinate plane; a
/// pair without a shared vertex that they cannot tell apart is intersected exactly on its
/// rational values, as the validator would; other pairs they cannot tell make it false, and
/// then the caller validates in full. Every other pair meets as it did. The pairs come from
/// [`MeetingBoxes`], or where fewer than one triangle in [`FEW_MOVED`] has a moved vertex from
/// an R-tree of those triangles' boxes; on rayon's threads from [`PARALLEL_FROM`] triangles.
pub(crate) fn conforming_after_moves<N: Num>(
    points: &[Point3<N>],
    tris: &[[usize; 3]],
    moved: &[bool],
) -> bool {
    let exact = &N::exact_ctx();
    let touched: Vec<usize> = (0..tris.len())
        .filter(|&t| tris[t].iter().any(|&v| moved[v]))
        .collect();
    // Few triangles moved (a rounded result): each triangle's box is looked up among theirs,
    // instead of pairing all boxes.
    let few = touched.len() * FEW_MOVED < tris.len();
    // Each point's nearest `f64`, once: the corners of the triangles' boxes, and the corners of
    // the triangles' planes, which tell most pairs apart with a few dot products before
    // anything is projected (prepared once where every pair is tested).
    let f64s: Vec<[f64; 3]> = points.iter().map(|p| p.to_f64()).collect();
    let plane = |t: [usize; 3]| SidePlane::of_triangle::<N>(&f64s, t);
    let planes: Vec<SidePlane> = match few {
        true => Vec::new(),
        false => tris.iter().map(|&t| plane(t)).collect(),
    };
    // Each triangle's image in a coordinate plane, where the planes cannot tell a pair apart:
    // made once, at its first such pair, where every pair is tested.
    let image = |t: [usize; 3]| Image::of(points, t, exact);
    let images: Vec<OnceLock<Option<Image>>> = match few {
        true => Vec::new(),
        false => tris.iter().map(|_| OnceLock::new()).collect(),
    };
    let stars = FlatStars::of(points, tris, exact);
    // Triangles `ti` and `ui` meet only in their shared corners (each test is symmetric).
    let meet_in_shared = |ti: usize, ui: usize| {
        if stars.meet_only_in_shared(ti, ui) {
            return true;
        }
        let (t, s) = (tris[ti], tris[ui]);
        let off = |t: [usize; 3], s: [usize; 3], ti: usize| match planes.get(ti) {
            Some(p) => off_plane_but_shared(t, s, |v| p.certain_side(f64s[v])),
            None => {
                let p = plane(t);
                off_plane_but_shared(t, s, |v| p.certain_side(f64s[v]))
            }
        };
        if off(t, s, ti) || off(s, t, ui) {
            return true;
        }
        let t_image = match images.get(ti) {
            Some(i) => *i.get_or_init(|| image(t)),
            None => image(t),
        };
        if t_image.is_some_and(|i| images_meet_only_in_shared(points, (t, &i), s, exact)) {
            true
        } else if t.iter().any(|v| s.contains(v)) {
            shared_only(points, t, s, exact).is_some()
        } else {
            let (t, s) = (t.map(|v| &points[v]), s.map(|v| &points[v]));
            // A float backend's pair is intersected on its exact values: its own arithmetic
            // would round the constructed ends of a contact, which could then miss each other.
            apart(t, s, exact)
                || if N::EXACT {
                    intersect(t, s, exact).is_none()
                } else {
                    let (t, s) = (t.map(exact_point), s.map(exact_point));
                    intersect(t.each_ref(), s.each_ref(), &()).is_none()
                }
        }
    };
    let boxes: Vec<AABB<[f64; 3]>> = (tris.iter())
        .map(|t| widened_box(t.map(|v| f64s[v])))
        .collect();
    let parallel = boxes.len() >= PARALLEL_FROM;
    let mut flags = vec![false; tris.len()];
    for &t in &touched {
        flags[t] = true;
    }
    if few {
        let tree = RTree::bulk_load(
            (touched.iter())
                .map(|&t| GeomWithData::new(Rectangle::from_aabb(boxes[t]), t))
                .collect(),
        );
        // Each pair once: two touched triangles from the later one.
        let near_touched = |u: usize| {
            (tree.locate_in_envelope_intersecting(&boxes[u]))
                .all(|g| g.data == u || flags[u] && g.data > u || meet_in_shared(g.data, u))
        };
        return match parallel {
            true => (0..tris.len()).into_par_iter().all(near_touched),
            false => (0..tris.len()).all(near_touched),
        };
    }
    MeetingBoxes::new(boxes).all_pairs(parallel, |t, u| {
        !(flags[t] || flags[u]) || meet_in_shared(t, u)
    })
}

/// A triangle's plane prepared for the side of many points by a filter: on `f64` values
/// (float mode), or on the nearest `f64`s of exact values.
enum SidePlane {
    Values(PlaneF64),
    Near(NearPlane),
}

impl SidePlane {
    /// The plane of the triangle `t` of points of backend `N`, indices into their nearest
    /// `f64`s `p`.
    fn of_triangle<N: Num>(p: &[[f64; 3]], t: [usize; 3]) -> SidePlane {
        match N::EXACT {
            true => SidePlane::Near(NearPlane::of_triangle(p, t)),
            false => SidePlane::Values(PlaneF64::of_triangle(p, t)),
        }
    }

    /// The side of the point `d` where the filter is certain of it.
    fn certain_side(&self, d: [f64; 3]) -> Option<Ordering> {
        match self {
            SidePlane::Values(p) => p.certain_side(d),
            SidePlane::Near(p) => p.certain_side(d),
        }
    }
}

/// [`conforming_after_moves`] looks up the triangles near the moved ones where these are fewer
/// than one in this many.
const FEW_MOVED: usize = 8;

impl Yin3Error {
    /// The same error with triangle indices replaced by the input faces they came from, and
    /// its points shown as `f64`s if `rounded` ([`Spot::shown`]).
    fn renumber_faces(self, origin: &[usize], rounded: bool) -> Yin3Error {
        let f = |t: usize| origin.get(t).copied().unwrap_or(t);
        match self {
            Yin3Error::OpenEdge {
                from,
                to,
                count,
                face,
            } => Yin3Error::OpenEdge {
                from: from.shown(rounded),
                to: to.shown(rounded),
                count,
                face: f(face),
            },
            Yin3Error::Inconsistent { from, to, a, b } => Yin3Error::Inconsistent {
                from: from.shown(rounded),
                to: to.shown(rounded),
                a: f(a),
                b: f(b),
            },
            Yin3Error::Orientation {
                face,
                winding,
                expected,
            } => Yin3Error::Orientation {
                face: f(face),
                winding,
                expected,
            },
            other => other,
        }
    }
}

/// The boundary bounded by `faces` over `vertices`, every decision exact (float mode too: its
/// ε applies to operations, not to validity); `rounded` if the vertices are the exact values
/// of a float-mode input (`f64`s), whose errors show points as `f64`s.
pub(super) fn build<N: Num>(
    vertices: &[Point3<N>],
    faces: &[Vec<usize>],
    rounded: bool,
) -> Result<Brep<N>, Yin3Error> {
    let exact = N::exact_ctx();
    let mut face_of = Vec::new();
    // The triangles over the used vertices, numbered in order of first use.
    let mut number: Vec<Option<usize>> = vec![None; vertices.len()];
    let mut used = Vec::new();
    let mut tris = Vec::with_capacity(faces.len());
    for (f, face) in faces.iter().enumerate() {
        for tri in face_triangles(vertices, face, f, &exact)? {
            tris.push(tri.map(|v| {
                *number[v].get_or_insert_with(|| {
                    used.push(v);
                    used.len() - 1
                })
            }));
            face_of.push(f);
        }
    }
    let mut soup = interned(vertices, &mut used);
    for t in tris {
        soup.push_interned(t.map(|k| used[k]), 0);
    }
    // A conforming complex (every two triangles meet only in shared corners and edges: most
    // meshes, and every stored result) is its own arrangement; only others are arranged. The
    // exact values of a float input are told apart as the `f64`s they are, whose planes'
    // filter decides most pairs with a few dot products.
    // Exact values on a common integer grid are told apart the same way, scaled to it.
    let everything = vec![true; soup.points.len()];
    let f64s = if rounded {
        let f64s = (soup.points.iter()).map(|p| {
            let [x, y, z] = p.to_f64();
            Point3::new(Float::new(x), Float::new(y), Float::new(z))
        });
        Some(f64s.collect())
    } else {
        on_grid(&soup.points)
    };
    let conforming = match f64s {
        Some(f64s) => conforming_after_moves::<Float>(&f64s, &soup.tris, &everything),
        None => conforming_after_moves(&soup.points, &soup.tris, &everything),
    };
    // The triangles of the boundary, and the input face of each.
    let (tris, origin) = if conforming {
        (std::mem::take(&mut soup.tris), face_of)
    } else {
        let arrangement = arrange(&mut soup, Pairs::All, &exact).map_err(|e| match e {
            ArrangeError::Clash {
                a,
                b,
                coplanar,
                point,
            } => {
                let (a, b, point) = (face_of[a], face_of[b], Spot::new(&point).shown(rounded));
                if coplanar {
                    Yin3Error::Overlap { a, b, point }
                } else {
                    Yin3Error::Crossing { a, b, point }
                }
            }
            ArrangeError::Internal(m) => Yin3Error::Internal(m),
        })?;
        let pieces = arrangement.pieces;
        let origin: Vec<usize> = pieces.iter().map(|(_, t)| face_of[*t]).collect();
        (pieces.into_iter().map(|(t, _)| t).collect(), origin)
    };
    let brep = Brep::assemble(soup.points, tris).map_err(|e| e.renumber_faces(&origin, rounded))?;
    check_windings(&brep, &exact).map_err(|e| e.renumber_faces(&origin, rounded))?;
    Ok(brep)
}

/// A soup of the vertices `used` (indices into `vertices`), equal ones merged, numbered in
/// order; each used vertex's index in it is written over its entry of `used`. Where the
/// vertices' nearest `f64`s are distinct (most meshes) so are the vertices, and no exact value
/// is hashed.
fn interned<N: Num>(vertices: &[Point3<N>], used: &mut [usize]) -> Soup<N> {
    // Adding 0.0 makes −0.0 the key of +0.0: both are the nearest f64 of an exact zero.
    let key = |v: usize| vertices[v].to_f64().map(|c| (c + 0.0).to_bits());
    let mut keys: HashSet<[u64; 3]> = HashSet::with_capacity(used.len());
    if used.iter().all(|&v| keys.insert(key(v))) {
        let points = used.iter().map(|&v| vertices[v].clone()).collect();
        used.iter_mut().enumerate().for_each(|(k, v)| *v = k);
        return Soup::of_distinct(points);
    }
    let mut soup = Soup::new();
    for v in used.iter_mut() {
        *v = soup.intern(&vertices[*v]);
    }
    soup
}

/// The context `ctx` resolved for `vertices` ([`Num::resolve_ctx`]: float mode's default ε
/// from the bounding box, or the error that the requested one is too fine for them).
pub(crate) fn resolve_for<N: Num>(
    vertices: &[Point3<N>],
    ctx: N::Ctx,
) -> Result<N::Ctx, Yin3Error> {
    let (span, magnitude) = BBox3::of(vertices).map_or((0.0, 0.0), |b| (b.span(), b.extent()));
    N::resolve_ctx(ctx, span, magnitude).map_err(|e| Yin3Error::ToleranceTooFine {
        requested: Float::new(e.requested),
        representable: Float::new(e.representable),
    })
}

/// The triangles of face `f` (a planar, simple polygon), as vertex index triples.
fn face_triangles<N: Num>(
    vertices: &[Point3<N>],
    face: &[usize],
    f: usize,
    ctx: &N::Ctx,
) -> Result<SmallVec<[[usize; 3]; 1]>, Yin3Error> {
    let degenerate = |reason: String| Yin3Error::DegenerateFace { face: f, reason };
    if face.len() < 3 {
        return Err(degenerate(format!(
            "{} vertices, a face needs at least 3",
            face.len()
        )));
    }
    if let Some(&index) = face.iter().find(|&&v| v >= vertices.len()) {
        return Err(Yin3Error::IndexOutOfRange {
            face: f,
            index,
            count: vertices.len(),
        });
    }
    for (i, v) in face.iter().enumerate() {
        if face[i + 1..].contains(v) {
            return Err(degenerate(format!("vertex {v} appears twice")));
        }
    }
    let p = |k: usize| &vertices[face[k]];
    let Some(k) = (2..face.len()).find(|&k| !collinear(p(0), p(1), p(k))) else {
        return Err(degenerate("all its vertices are collinear".into()));
    };
    if let Some(i) =
        (k + 1..face.len()).find(|&i| orient3d(p(0), p(1), p(k), p(i), ctx) != Ordering::Equal)
    {
        return Err(Yin3Error::NonPlanarFace {
            face: f,
            count: face.len(),
            vertex: face[i],
        });
    }
    if face.len() == 3 {
        return Ok(smallvec![[face[0], face[1], face[2]]]);
    }
    // The polygon's orientation in the chart of its plane decides how its ears are read.
    let chart = Chart::of_normal(&polygon_normal(vertices, face));
    let pts: Vec<Point<N>> = face.iter().map(|&v| chart.project(&vertices[v])).collect();
    let ears = ear_clip(&pts, &(0..face.len()).collect::<Vec<_>>(), ctx)
        .ok_or_else(|| degenerate("the polygon is not simple".into()))?;
    Ok(ears.into_iter().map(|t| t.map(|k| face[k])).collect())
}

/// Newell's normal of a planar polygon: twice its vector area, pointing by the right-hand rule.
fn polygon_normal<N: Num>(vertices: &[Point3<N>], face: &[usize]) -> Point3<N> {
    let o = &vertices[face[0]];
    (1..face.len() - 1).fold(Point3::int(0, 0, 0), |s, i| {
        let n = normal(o, &vertices[face[i]], &vertices[face[i + 1]]);
        Point3::new(s.x + n.x, s.y + n.y, s.z + n.z)
    })
}

/// I4: on the side its normals point to, each edge-connected closed surface has winding
/// number 0 (bounded set) or −1 (unbounded set), by one ray per surface.
pub(crate) fn check_windings<N: Num>(b: &Brep<N>, ctx: &N::Ctx) -> Result<(), Yin3Error> {
    let mut uf = UnionFind::new(b.tris.len());
    for fins in b.table.fin_lists() {
        for f in &fins[1..] {
            uf.union(fins[0].tri, f.tri);
        }
    }
    let (label, count) = uf.classes();
    let expected = if b.bounded { 0 } else { -1 };
    // Each triangle's box on its corners rounded to f64, each point rounded once, each box
    // made once for the rays of all the surfaces.
    let rounded: Vec<[f64; 3]> = b.points.iter().map(Point3::to_f64).collect();
    let boxes: Vec<AABB<[f64; 3]>> = (b.tris.iter())
        .map(|t| widened_box(t.map(|v| rounded[v])))
        .collect();
    // For each surface, a triangle whose normal has a nonzero x (the orientation of its
    // projection to the yz-plane): the ray along +x leaves it to one side.
    let yz = |p: &Point3<N>| Point::new(p.y.clone(), p.z.clone());
    let mut leaving: Vec<Option<(usize, Ordering)>> = vec![None; count];
    for (t, &c) in label.iter().enumerate() {
        if leaving[c].is_none() {
            let [p, q, r] = b.corners(t);
            let s = orient(&yz(p), &yz(q), &yz(r), ctx);
            leaving[c] = (s != Ordering::Equal).then_some((t, s));
        }
    }
    for (t, nx) in leaving.into_iter().flatten() {
        let [p, q, r] = b.corners(t);
        let centroid = Point3::centroid(p, q, r);
        let ray = ray_box(&centroid);
        let others = (0..b.tris.len())
            .filter(|&u| u != t && boxes[u].intersects(&ray))
            .map(|u| b.corners(u));
        let w = winding(others, &centroid, ctx);
        // The ray runs into the +n side if the normal's x is positive; the −n side has one more.
        let plus = if nx == Ordering::Greater { w } else { w - 1 };
        if plus != expected {
            return Err(Yin3Error::Orientation {
                face: t,
                winding: plus,
                expected,
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;
    use crate::yin3::grid::tests::{point, tetrahedron};
    use crate::yin3::shapes::{concat, cuboid};
    use rand::SeedableRng;

    /// The cubes [0, 10]³ and [15, 25]³ in backend `N`, and `far` unit cubes far from them,
    /// with the corners `moves` moved: the local check and the full validator (on the exact
    /// values).
    fn after_moving<N: Num>(moves: &[([i64; 3], [i64; 3])], far: i64) -> (bool, bool) {
        let p =
            |v: [i64; 3]| Point3::<N>::new(N::from_i64(v[0]), N::from_i64(v[1]), N::from_i64(v[2]));
        let mut cubes = vec![
            cuboid(&p([0; 3]), &p([10; 3])),
            cuboid(&p([15; 3]), &p([25; 3])),
        ];
        cubes.extend((0..far).map(|k| cuboid(&p([100 + 2 * k, 0, 0]), &p([101 + 2 * k, 1, 1]))));
        let (v, f) = concat(cubes);
        let b = YinSet3::from_triangles(v, f)
            .expect("two cubes")
            .brep()
            .expect("bounded")
            .clone();
        let to = |q: &Point3<N>| {
            moves
                .iter()
                .find(|(from, _)| *q == p(*from))
                .map(|m| p(m.1))
        };
        let moved: Vec<bool> = b.points.iter().map(|q| to(q).is_some()).collect();
        let after = b.map_points(|q| to(q).unwrap_or_else(|| q.clone()));
        // The far cubes put the moved triangles below one in FEW_MOVED: the R-tree's path.
        let touched = (after.tris.iter())
            .filter(|t| t.iter().any(|&v| moved[v]))
            .count();
        assert_eq!(touched * FEW_MOVED < after.tris.len(), far > 0);
        let full = revalidate(exact_points(&after.points), &after, ()).is_ok();
        (
            conforming_after_moves(&after.points, &after.tris, &moved),
            full,
        )
    }

    /// Revalidation compares the stored glued surfaces and Hasse diagram with the rebuilt
    /// ones: two disjoint cubes pass as stored, and fail with their surfaces listed the other
    /// way round, or with one cube recorded inside the other.
    #[test]
    fn revalidation_finds_a_wrong_surface_list_or_hasse_diagram() {
        let p = |v: i64| Point3::<Rational>::int(v, v, v);
        let (v, f) = concat(vec![cuboid(&p(0), &p(10)), cuboid(&p(15), &p(25))]);
        let set = YinSet3::from_triangles(v, f).expect("two cubes");
        let b = set.brep().expect("bounded");
        assert!(revalidate(b.points.clone(), b, ()).is_ok());
        assert_eq!(b.parent, [None, None]);
        let mut swapped = b.clone();
        swapped.surfaces.swap(0, 1);
        let mut nested = b.clone();
        nested.parent[1] = Some(0);
        for wrong in [swapped, nested] {
            let result = revalidate(wrong.points.clone(), &wrong, ());
            assert!(matches!(result, Err(Yin3Error::Internal(_))), "{result:?}");
        }
    }

    /// A cube of side 2·10³⁰⁹ around a unit cavity is valid: its faces lie past `f64`'s range,
    /// and the winding check's ray from the cavity still meets them (their boxes start at
    /// `f64::MAX`, not at infinity).
    #[test]
    fn a_cavity_in_a_cube_past_f64s_range_is_valid() {
        let r = |v: Rational| Point3::new(v.clone(), v.clone(), v);
        let big = Rational::from_integer(num_bigint::BigInt::from(10).pow(309));
        let one = Rational::from_i64(1);
        let (mut cavity, outer) = (
            cuboid(&r(-one.clone()), &r(one)),
            cuboid(&r(-big.clone()), &r(big)),
        );
        cavity.1.iter_mut().for_each(|f| f.reverse());
        let (v, f) = concat(vec![outer, cavity]);
        let set = YinSet3::<Rational>::from_triangles(v, f).expect("a cube around a cavity");
        assert_eq!(set.betti().b2, 1);
    }

    /// A float-mode input's errors show its points as the `f64`s they are: the open edge of a
    /// lone triangle with corners 0.1, 0.2 and 0.3 on the axes is between two of
    /// (0.1, 0, 0), (0, 0.2, 0) and (0, 0, 0.3), not their exact binary fractions.
    #[test]
    fn a_float_inputs_error_shows_its_points_as_f64s() {
        let p = |x, y, z| Point3::new(Float::new(x), Float::new(y), Float::new(z));
        let corners = vec![p(0.1, 0.0, 0.0), p(0.0, 0.2, 0.0), p(0.0, 0.0, 0.3)];
        let e = YinSet3::from_triangles(corners, vec![vec![0, 1, 2]]).expect_err("open");
        let Yin3Error::OpenEdge { from, to, .. } = &e else {
            panic!("expected OpenEdge, got {e:?}");
        };
        let shown = ["(0.1, 0, 0)", "(0, 0.2, 0)", "(0, 0, 0.3)"];
        for end in [from, to] {
            assert!(shown.contains(&end.to_string().as_str()), "{e}");
        }
    }

    /// In both backends (float points take the plane test first), with few triangles beside
    /// the moved ones (every pair of boxes swept) and with many (the boxes near the moved
    /// triangles looked up).
    #[test]
    fn a_moved_vertex_is_checked_against_its_neighbours() {
        for far in [0, 16] {
            moved_vertices_checked::<Rational>(far);
            moved_vertices_checked::<Float>(far);
        }
    }

    fn moved_vertices_checked<N: Num>(far: i64) {
        let after_moving = |moves: &[([i64; 3], [i64; 3])]| after_moving::<N>(moves, far);
        let corner = [10; 3];
        // Pulled out a little: still valid.
        assert_eq!(after_moving(&[(corner, [11, 11, 11])]), (true, true));
        // Into the other cube: its faces cross the other's.
        assert_eq!(after_moving(&[(corner, [17, 17, 17])]), (false, false));
        // Both moved, crossing each other's faces.
        assert_eq!(
            after_moving(&[(corner, [17, 17, 17]), ([15; 3], [14; 3])]),
            (false, false)
        );
        // Onto a face of the other cube: a contact the stored triangles do not conform to.
        assert_eq!(after_moving(&[(corner, [15, 17, 17])]), (false, false));
        // Folded over a neighbour across a shared edge, in its plane.
        assert_eq!(after_moving(&[(corner, [4, 4, 10])]), (false, false));
        // Onto the line of an edge of its own: a degenerate triangle.
        assert_eq!(after_moving(&[(corner, [20, -10, 10])]), (false, false));
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(
            yinset_testkit::cases(256)
        ))]
        /// The soup of the used vertices has one point per distinct value, in order of first
        /// use, and maps each used vertex to its value, against a scan for equal values; the
        /// values are thirds, some z's plus 10⁻³⁰ (n/3 + 10⁻³⁰ has the nearest `f64` of n/3
        /// for n ≠ 0), so both the path without hashing and the one with it are taken.
        #[test]
        fn interned_merges_equal_vertices_only(
            coords in proptest::collection::vec((0i64..3, 0i64..3, 0i64..2, proptest::bool::ANY), 1..12),
            used in proptest::collection::vec(0usize..12, 1..16),
        ) {
            let tiny = Rational::new(1.into(), num_bigint::BigInt::from(10).pow(30));
            let value = |n: i64, nudged: bool| {
                let v = Rational::new(n.into(), 3.into());
                if nudged { v + tiny.clone() } else { v }
            };
            let vertices: Vec<Point3<Rational>> = coords
                .iter()
                .map(|&(x, y, z, nudged)| Point3::new(value(x, false), value(y, false), value(z, nudged)))
                .collect();
            let mut used: Vec<usize> = used.into_iter().map(|v| v % vertices.len()).collect();
            let given = used.clone();
            let soup = interned(&vertices, &mut used);
            let mut distinct: Vec<&Point3<Rational>> = Vec::new();
            for &v in &given {
                if !distinct.contains(&&vertices[v]) {
                    distinct.push(&vertices[v]);
                }
            }
            proptest::prop_assert_eq!(soup.points.iter().collect::<Vec<_>>(), distinct);
            for (k, &v) in given.iter().enumerate() {
                proptest::prop_assert_eq!(&soup.points[used[k]], &vertices[v]);
            }
        }
    }

    /// The triangles of two tetrahedra on the grid of tenths, as one soup (equal corners
    /// shared): they cross, touch or miss. Whether the soup is conforming is the same on the
    /// rationals and on their images on the common grid, and both verdicts occur often.
    #[test]
    fn conformity_is_decided_alike_on_the_grid() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(11);
        let mut verdicts = [0usize; 2];
        for _ in 0..400 {
            let (Some(t), Some(s)) = (tetrahedron(&mut rng), tetrahedron(&mut rng)) else {
                continue;
            };
            let mut soup = Soup::new();
            for b in [t.brep().expect("bounded"), s.brep().expect("bounded")] {
                for k in 0..b.tris.len() {
                    soup.push(b.corners(k), 0);
                }
            }
            let everything = vec![true; soup.points.len()];
            let exact = conforming_after_moves(&soup.points, &soup.tris, &everything);
            let scaled = on_grid(&soup.points).expect("tenths are on a grid");
            assert_eq!(
                conforming_after_moves(&scaled, &soup.tris, &everything),
                exact
            );
            verdicts[usize::from(exact)] += 1;
        }
        assert!(verdicts.iter().all(|&n| n >= 40), "verdicts {verdicts:?}");
    }

    /// A corner of one triangle inside an edge of another, at 4/11 of it, the planes
    /// crossing there: the two meet in that point, which `f64` arithmetic on the grid images
    /// rounds apart (the constructed ends of the contact miss each other), so conformity must
    /// be decided on the exact values either way.
    #[test]
    fn a_corner_inside_an_edge_is_no_conforming_contact() {
        let corners = [
            [-57, 35, -165],
            [88, 231, 187],
            [209, 286, 297],
            [-165, 11, -231],
            [231, 99, 11],
            [22, -275, -297],
        ];
        let points: Vec<Point3<Rational>> =
            corners.iter().map(|&[x, y, z]| point(x, y, z, 1)).collect();
        let tris = [[0, 1, 2], [3, 4, 5]];
        let everything = [true; 6];
        assert!(!conforming_after_moves(&points, &tris, &everything));
        let images = on_grid(&points).expect("integers are on a grid");
        assert!(!conforming_after_moves(&images, &tris, &everything));
    }
}
