//! `info`: a Yin set's topology, size and extent as a JSON object (2D and 3D).

use crate::kernel::{Point, Point3};
use crate::num::{Num, Rational};
use crate::yin2::YinSet2;
use crate::yin3::YinSet3;
use serde_json::{json, Value};

/// The JSON report on `set`. Every number is given as its exact value in text (`p/q` where it
/// is not an integer; in float mode the exact value of the `f64`s, and the exact area of the
/// `f64` vertices) and as the nearest `f64` (`null` beyond the range of `f64`).
pub fn report<N: Num>(set: &YinSet2<N>) -> Value {
    let betti = set.betti();
    let homology = set.homology();
    let kind = kind(set.is_empty(), set.is_full(), "spadjor");
    let curves: Vec<Value> = set
        .curves()
        .iter()
        .zip(set.parents())
        .enumerate()
        .map(|(k, (c, parent))| {
            json!({
                "curve": k,
                "orientation": if c.is_positive() { "positive" } else { "negative" },
                "vertices": c.len(),
                "parent": parent,
            })
        })
        .collect();
    let atoms: Vec<Value> = set
        .atoms()
        .iter()
        .map(|a| json!({ "outer": a.outer, "holes": a.holes }))
        .collect();
    json!({
        "dimension": 2,
        "exact": N::EXACT,
        "set": kind,
        "bounded": set.is_bounded(),
        "betti": {
            "components": betti.components,
            "holes": betti.holes,
            "total_holes": betti.total_holes,
        },
        // Homological b0, b1 (YinSet2::homology): differ from the seed's count where holes
        // touch.
        "homology": { "b0": homology.b0, "b1": homology.b1 },
        "curves": set.curves().len(),
        "vertices": set.curves().iter().map(|c| c.len()).sum::<usize>(),
        "hasse": curves,
        "atoms": atoms,
        "area": set.area_exact().map(measure),
        "bbox": set.bbox().map(|b| json!({ "min": point(&b.min), "max": point(&b.max) })),
    })
}

/// The one-line summary `validate` gives of `set`: curves, Betti numbers, boundedness. Not its
/// exact area, which `info` reports: an exact result's area can have far more digits than its
/// coordinates (320 576 characters for the meet of two 10⁴-vertex stars), and summing it took
/// 80% of the time of reading such a result back.
pub fn summary<N: Num>(set: &YinSet2<N>) -> String {
    let b = set.betti();
    let extent = if set.is_bounded() {
        "bounded (its area: yinset info)"
    } else {
        "unbounded"
    };
    format!(
        "{} curves, b0 = {}, holes per component {:?}, {extent}",
        set.curves().len(),
        b.components,
        b.holes
    )
}

/// The JSON report on the 3D `set`, in the terms of the 2D one: volume for area, surfaces
/// (glued surfaces, each with its parent in the Hasse diagram) for curves.
pub fn report3<N: Num>(set: &YinSet3<N>) -> Value {
    let betti = set.betti();
    let surfaces: Vec<Value> = set
        .surfaces()
        .iter()
        .zip(set.parents())
        .enumerate()
        .map(|(k, (s, parent))| {
            json!({
                "surface": k,
                "triangles": s.triangles.len(),
                "positive": s.positive,
                "genus": s.genus,
                "parent": parent,
            })
        })
        .collect();
    let atoms: Vec<Value> = set
        .atoms()
        .iter()
        .map(|a| json!({ "outer": a.outer, "inner": a.inner }))
        .collect();
    json!({
        "dimension": 3,
        "exact": N::EXACT,
        "set": kind(set.is_empty(), set.is_full(), "brep"),
        "bounded": set.is_bounded(),
        "b0": betti.b0,
        "b1": betti.b1,
        "b2": betti.b2,
        "surfaces": surfaces,
        "atoms": atoms,
        "vertices": set.vertices().len(),
        "triangles": set.triangles().len(),
        "volume": set.volume_exact().map(measure),
        "bbox": set.bbox().map(|b| json!({ "min": point3(&b.min), "max": point3(&b.max) })),
    })
}

/// What the set is: `empty` (0̂), `full` (1̂) or `boundary`, the kind of boundary it has.
fn kind(empty: bool, full: bool, boundary: &'static str) -> &'static str {
    if empty {
        "empty"
    } else if full {
        "full"
    } else {
        boundary
    }
}

/// An exact value as its text and its nearest `f64` (`null` where that is infinite).
fn measure(v: Rational) -> Value {
    let float = Some(v.to_f64()).filter(|f| f.is_finite());
    json!({ "exact": v.to_string(), "float": float })
}

/// A number of the backend as [`measure`] gives its exact value.
fn number<N: Num>(v: &N) -> Value {
    let (n, d) = v.fraction();
    measure(Rational::new(n, d))
}

/// A point as `[x, y]` of [`number`]s.
fn point<N: Num>(p: &Point<N>) -> Value {
    json!([number(&p.x), number(&p.y)])
}

/// A point as `[x, y, z]` of [`number`]s.
fn point3<N: Num>(p: &Point3<N>) -> Value {
    json!([number(&p.x), number(&p.y), number(&p.z)])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reports_topology_area_and_box_exactly() {
        let p = |x, y| Point::int(x, y);
        let hole = vec![p(1, 1), p(1, 2), p(2, 1)];
        let set =
            YinSet2::<Rational>::from_curves(vec![vec![p(0, 0), p(6, 0), p(0, 6)], hole]).unwrap();
        let r = report(&set);
        assert_eq!(
            r["betti"],
            json!({"components": 1, "holes": [1], "total_holes": 1})
        );
        assert_eq!(r["homology"], json!({"b0": 1, "b1": 1}));
        assert_eq!(r["area"]["exact"], "35/2");
        assert_eq!(
            summary(&set),
            "2 curves, b0 = 1, holes per component [1], bounded (its area: yinset info)"
        );
        assert_eq!(r["area"]["float"], 17.5);
        assert_eq!(r["hasse"][1]["parent"], 0);
        assert_eq!(r["hasse"][0]["parent"], Value::Null);
        assert_eq!(r["bbox"]["max"][0]["exact"], "6");
        assert_eq!(r["vertices"], 6);
        let outside = report(&set.complement());
        assert_eq!(
            (outside["bounded"].clone(), outside["area"].clone()),
            (json!(false), Value::Null)
        );
        assert_eq!(report(&YinSet2::<Rational>::full())["set"], "full");
    }

    #[test]
    fn reports_3d_betti_volume_surfaces_and_box() {
        let v = |x, y, z| Point3::int(x, y, z);
        // A corner tetrahedron with legs 2, normals out: volume 2³/6 = 4/3.
        let tetra = YinSet3::<Rational>::from_triangles(
            vec![v(0, 0, 0), v(2, 0, 0), v(0, 2, 0), v(0, 0, 2)],
            vec![vec![0, 2, 1], vec![0, 1, 3], vec![1, 2, 3], vec![2, 0, 3]],
        )
        .unwrap();
        let r = report3(&tetra);
        assert_eq!(r["dimension"], 3);
        assert_eq!(
            (r["b0"].clone(), r["b1"].clone(), r["b2"].clone()),
            (json!(1), json!(0), json!(0))
        );
        assert_eq!(r["volume"]["exact"], "4/3");
        assert_eq!(
            r["surfaces"],
            json!([{"surface": 0, "triangles": 4, "positive": true, "genus": 0, "parent": null}])
        );
        assert_eq!(r["atoms"], json!([{"outer": 0, "inner": []}]));
        assert_eq!(r["bbox"]["max"][2]["exact"], "2");
        assert_eq!(
            (r["vertices"].clone(), r["triangles"].clone()),
            (json!(4), json!(4))
        );
        let outside = report3(&tetra.complement());
        assert_eq!(
            (outside["bounded"].clone(), outside["volume"].clone()),
            (json!(false), Value::Null)
        );
        assert_eq!(outside["surfaces"][0]["positive"], false);
        assert_eq!(report3(&YinSet3::<Rational>::full())["set"], "full");
        assert_eq!(
            report3(&YinSet3::<Rational>::empty())["volume"]["exact"],
            "0"
        );
    }
}
