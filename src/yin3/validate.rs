//! Construction from user triangles and the public validator (DESIGN-3D §2.2): faces are
//! checked and triangulated, legal contacts (T-junctions, a vertex or an edge on a face) made
//! conforming by the arrangement of the faces against each other, and invariants I1–I4
//! checked, with errors naming the face or edge at fault.

use super::arrange::{arrange, ArrangeError, Pairs, Soup};
use super::error::Yin3Error;
use super::geom::{normal, Chart};
use super::locate::winding;
use super::set::{Brep, YinSet3};
use super::triangulate::ear_clip;
use crate::kernel::{orient3d, Point, Point3};
use crate::num::Num;
use crate::union_find::UnionFind;
use std::cmp::Ordering;

impl<N: Num> YinSet3<N> {
    /// The 3D Yin set bounded by the given faces: `vertices` and, per face, its vertex indices
    /// (0-based) in counterclockwise order seen from outside (normals point out of the set by
    /// the right-hand rule). Planar n-gons are triangulated; T-junctions and vertices or edges
    /// lying on faces are made conforming. Errors name the face or edge at fault.
    ///
    /// ```
    /// use yinset::{kernel::Point3, num::{Num, Rational}, yin3::YinSet3};
    /// let v: Vec<Point3<Rational>> = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    ///     .iter().map(|&(x, y, z)| Point3::int(x, y, z)).collect();
    /// let faces = vec![vec![0, 3, 2, 1], vec![4, 5, 6, 7], vec![0, 1, 5, 4], vec![1, 2, 6, 5], vec![2, 3, 7, 6], vec![3, 0, 4, 7]];
    /// let cube = YinSet3::from_triangles(v, faces)?;
    /// assert_eq!(cube.volume(), Some(Rational::from_i64(1)));
    /// assert_eq!((cube.betti().b0, cube.betti().b1, cube.betti().b2), (1, 0, 0));
    /// # Ok::<(), yinset::yin3::Yin3Error>(())
    /// ```
    pub fn from_triangles(
        vertices: Vec<Point3<N>>,
        faces: Vec<Vec<usize>>,
    ) -> Result<YinSet3<N>, Yin3Error> {
        YinSet3::from_triangles_with(vertices, faces, N::Ctx::default())
    }

    /// As [`YinSet3::from_triangles`], with the given number context.
    pub fn from_triangles_with(
        vertices: Vec<Point3<N>>,
        faces: Vec<Vec<usize>>,
        ctx: N::Ctx,
    ) -> Result<YinSet3<N>, Yin3Error> {
        if faces.is_empty() {
            return Err(Yin3Error::NoFaces);
        }
        if let Some(v) = vertices
            .iter()
            .position(|p| p.coords().iter().any(|c| !c.is_finite()))
        {
            return Err(Yin3Error::NotFinite { vertex: v });
        }
        let mut soup = Soup::new();
        let mut face_of = Vec::new();
        for (f, face) in faces.iter().enumerate() {
            for tri in face_triangles(&vertices, face, f, &ctx)? {
                soup.push(tri.map(|v| &vertices[v]), 0);
                face_of.push(f);
            }
        }
        let pieces = arrange(&mut soup, Pairs::All, &ctx).map_err(|e| match e {
            ArrangeError::Clash {
                a,
                b,
                coplanar,
                point,
            } => {
                let (a, b, point) = (face_of[a], face_of[b], point.to_string());
                if coplanar {
                    Yin3Error::Overlap { a, b, point }
                } else {
                    Yin3Error::Crossing { a, b, point }
                }
            }
            ArrangeError::Internal(m) => Yin3Error::Internal(m),
        })?;
        let origin: Vec<usize> = pieces.iter().map(|(_, t)| face_of[*t]).collect();
        let tris: Vec<[usize; 3]> = pieces.into_iter().map(|(t, _)| t).collect();
        let brep =
            Brep::assemble(soup.points, tris, &ctx).map_err(|e| e.renumber_faces(&origin))?;
        check_windings(&brep, &ctx).map_err(|e| e.renumber_faces(&origin))?;
        Ok(YinSet3::from_brep(brep, ctx))
    }

    /// Check that the stored boundary is a valid boundary representation (I1–I4), as
    /// [`YinSet3::from_triangles`] would accept it unchanged; every operation's output passes.
    pub fn validate(&self) -> Result<(), Yin3Error> {
        let Some(b) = self.brep() else {
            return Ok(());
        };
        let faces = b.tris.iter().map(|t| t.to_vec()).collect();
        let again = YinSet3::from_triangles_with(b.points.clone(), faces, self.ctx)?;
        let rebuilt = again.brep().expect("a non-empty boundary");
        if rebuilt.tris.len() != b.tris.len() {
            return Err(Yin3Error::Internal(format!(
                "the stored triangles are not conforming: validation re-cut {} triangles into {}",
                b.tris.len(),
                rebuilt.tris.len()
            )));
        }
        if rebuilt.surfaces != b.surfaces
            || rebuilt.parent != b.parent
            || rebuilt.bounded != b.bounded
        {
            return Err(Yin3Error::Internal(
                "the stored glued surfaces or Hasse diagram differ from the recomputed ones".into(),
            ));
        }
        Ok(())
    }
}

impl Yin3Error {
    /// The same error with triangle indices replaced by the input faces they came from.
    fn renumber_faces(self, origin: &[usize]) -> Yin3Error {
        let f = |t: usize| origin.get(t).copied().unwrap_or(t);
        match self {
            Yin3Error::OpenEdge {
                from,
                to,
                count,
                face,
            } => Yin3Error::OpenEdge {
                from,
                to,
                count,
                face: f(face),
            },
            Yin3Error::Inconsistent { from, to, a, b } => Yin3Error::Inconsistent {
                from,
                to,
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

/// The triangles of face `f` (a planar, simple polygon), as vertex index triples.
fn face_triangles<N: Num>(
    vertices: &[Point3<N>],
    face: &[usize],
    f: usize,
    ctx: &N::Ctx,
) -> Result<Vec<[usize; 3]>, Yin3Error> {
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
    let zero = Point3::int(0, 0, 0);
    let Some(k) = (2..face.len()).find(|&k| normal(p(0), p(1), p(k)) != zero) else {
        return Err(degenerate("all its vertices are collinear".into()));
    };
    if let Some(i) =
        (2..face.len()).find(|&i| orient3d(p(0), p(1), p(k), p(i), ctx) != Ordering::Equal)
    {
        return Err(Yin3Error::NonPlanarFace {
            face: f,
            count: face.len(),
            vertex: face[i],
        });
    }
    if face.len() == 3 {
        return Ok(vec![[face[0], face[1], face[2]]]);
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
fn check_windings<N: Num>(b: &Brep<N>, ctx: &N::Ctx) -> Result<(), Yin3Error> {
    let mut uf = UnionFind::new(b.tris.len());
    for fins in &b.table.fins {
        for f in &fins[1..] {
            uf.union(fins[0].tri, f.tri);
        }
    }
    let (label, count) = uf.classes();
    let expected = if b.bounded { 0 } else { -1 };
    for c in 0..count {
        // A triangle whose normal has a nonzero x: the ray along +x leaves it to one side.
        let Some((t, nx)) = (0..b.tris.len()).filter(|&t| label[t] == c).find_map(|t| {
            let [p, q, r] = b.corners(t);
            let s = normal(p, q, r).x.sign();
            (s != Ordering::Equal).then_some((t, s))
        }) else {
            continue;
        };
        let [p, q, r] = b.corners(t);
        let centroid = Point3::centroid(p, q, r);
        let others = (0..b.tris.len()).filter(|&u| u != t).map(|u| b.corners(u));
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
