//! `info`: a Yin set's topology, size and extent as a JSON object.

use crate::kernel::Point;
use crate::num::Num;
use crate::yin2::YinSet2;
use serde_json::{json, Value};

/// The JSON report on `set`. Numbers of the backend are given as text (`p/q` in exact mode)
/// and as the nearest `f64`.
pub fn report<N: Num>(set: &YinSet2<N>) -> Value {
    let betti = set.betti();
    let kind = if set.is_empty() {
        "empty"
    } else if set.is_full() {
        "full"
    } else {
        "spadjor"
    };
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
        "exact": N::EXACT,
        "set": kind,
        "bounded": set.is_bounded(),
        "betti": {
            "components": betti.components,
            "holes": betti.holes,
            "total_holes": betti.total_holes,
        },
        "curves": set.curves().len(),
        "vertices": set.curves().iter().map(|c| c.len()).sum::<usize>(),
        "hasse": curves,
        "atoms": atoms,
        "area": set.area().map(|a| number(&a)),
        "bbox": set.bbox().map(|b| json!({ "min": point(&b.min), "max": point(&b.max) })),
    })
}

/// A number as its exact text and its nearest `f64`.
fn number<N: Num>(v: &N) -> Value {
    json!({ "exact": v.to_string(), "float": v.to_f64() })
}

/// A point as `[x, y]` of [`number`]s.
fn point<N: Num>(p: &Point<N>) -> Value {
    json!([number(&p.x), number(&p.y)])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;

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
        assert_eq!(r["area"]["exact"], "35/2");
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
}
