//! The properties of the 3D float-mode target `ops3_float` (README, "3D float mode"), against
//! exact mode run on the same `f64` values read as rationals (as tests/float_mode3.rs does).
//!
//! The operands are `ops3_exact`'s: two lattice solids combined, optionally complemented and
//! rotated, built exactly ([`crate::check3::build_operand`]). Their boundary triangles are
//! then given `f64` vertices: A's the nearest `f64`s of its exact vertices, B's the same after
//! the input's move ([`Place3`]: none, a shift by k·2^-j, a per-axis scale about (2, 2, 2), or
//! a shift by the `f64` nearest k·2^-j/3), everything times 2^s. Unmoved or moved by a
//! multiple of a coarse unit, the operands keep shared faces, edges and vertices (the general
//! exact path of the float meet); moved by a fine one, their triangles mostly cross properly
//! (the transversal path, src/yin3/transversal.rs). Rotated, the lattice values are rounded
//! (full mantissas), so that shared faces become nearly but not exactly coplanar; B is then
//! not moved (moving it too puts both operands' full-mantissa values in general position,
//! where the exact oracle takes seconds per input: the meet of F with the nearly coincident E).
//!
//! The oracle runs unscaled: each operand is built in exact mode from the `f64` values divided
//! by 2^s (exact: a power of two), independently of the float code, and the float results'
//! values are read back the same way. Scaling by a power of two changes no incidence and no
//! rounding, so the oracle's arithmetic stays small at any scale.

use crate::check::fail;
use crate::check3::{build_operand, probe_point};
use crate::input3::{Ops3Input, Place3, MOVE_NONE, MOVE_SCALE, MOVE_SHIFT, MOVE_THIRDS, ROTATE};
use std::cmp::Ordering;
use std::fmt::Debug;
use yinset::kernel::Point3;
use yinset::num::{Float, Num, Rational, Tolerance};
use yinset::yin2::Location;
use yinset::yin3::{Yin3Error, YinSet3};
use yinset_testkit::ops::{exact_of, pow2, OPS};
use yinset_testkit::shapes::show3;
use yinset_testkit::{P3, Y3};

type F3 = YinSet3<Float>;

/// The constant C of the README's bound vol(F △ E) ≤ C·ε·A (3D float mode, "ε").
pub const VOLUME_C: f64 = 1.0;

/// The exact value of a finite `f64`.
fn exact(v: f64) -> Rational {
    Rational::from_f64(v).expect("finite coordinates")
}

/// The `f64` value (unscaled) of coordinate `x` on axis `c`: B's move applied if `moved`, to
/// the nearest `f64`.
fn placed(x: &Rational, c: usize, place: &Place3, moved: bool) -> f64 {
    let one = || Rational::from_i64(1);
    let step = || Rational::from_i64(i64::from(place.k[c])) * pow2(-i32::from(place.exp));
    let value = match (moved, place.mode) {
        (false, _) | (_, MOVE_NONE) => x.clone(),
        (_, MOVE_SHIFT) => x.clone() + step(),
        (_, MOVE_SCALE) => {
            let two = Rational::from_i64(2);
            two.clone() + (x.clone() - two) * (one() + step())
        }
        _ => {
            debug_assert_eq!(place.mode, MOVE_THIRDS);
            // The shift itself an f64 first (full mantissa), then added and rounded.
            x.clone() + exact((step() / Rational::from_i64(3)).to_f64())
        }
    };
    value.to_f64()
}

/// One operand in both modes: the exact set of its (unscaled) `f64` values and the float set
/// of the scaled ones.
struct Both {
    exact: Y3,
    float: F3,
}

/// The largest side of the bounding box and the largest coordinate magnitude of `f64` points,
/// as the kernel's `BBox3::span` and `extent` compute them (for the ε it must refuse).
fn span_and_magnitude(pts: &[[f64; 3]]) -> (f64, f64) {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for p in pts {
        for c in 0..3 {
            lo[c] = lo[c].min(p[c]);
            hi[c] = hi[c].max(p[c]);
        }
    }
    let side = |c: usize| hi[c] / 2.0 - lo[c] / 2.0;
    let span = (2.0 * side(0).max(side(1)).max(side(2))).min(f64::MAX);
    let magnitude = lo.iter().chain(&hi).map(|v| v.abs()).fold(0.0, f64::max);
    (span, magnitude)
}

/// Operand `y` in both modes (B's move applied if `moved`); `None` when its `f64` values bound
/// no set (both modes reject them) or ε is too fine for them (float mode refuses, as it
/// must). Checks that float mode accepts exactly what exact mode accepts on the same values,
/// refuses ε with `ToleranceTooFine` exactly when its grid is finer than the coordinates can
/// carry, and that an accepted float set is valid and is the exact set of its values.
fn operand<D: Debug>(name: &str, y: &Y3, moved: bool, place: &Place3, input: &D) -> Option<Both> {
    if y.is_empty() || y.is_full() {
        let float = if y.is_empty() {
            F3::empty()
        } else {
            F3::full()
        };
        return Some(Both {
            exact: y.clone(),
            float,
        });
    }
    let s = place.exponent();
    let up = 2f64.powi(s);
    let values: Vec<[f64; 3]> = y
        .vertices()
        .iter()
        .map(|p| [0, 1, 2].map(|c| placed(p.coord(c), c, place, moved)))
        .collect();
    let faces: Vec<Vec<usize>> = y.triangles().iter().map(|t| t.to_vec()).collect();
    let exact_pts = values
        .iter()
        .map(|v| Point3::new(exact(v[0]), exact(v[1]), exact(v[2])))
        .collect();
    let scaled: Vec<[f64; 3]> = values.iter().map(|v| v.map(|c| c * up)).collect();
    let float_pts = scaled
        .iter()
        .map(|v| Point3::new(Float::new(v[0]), Float::new(v[1]), Float::new(v[2])))
        .collect();
    let eps = place.eps() * up;
    let (span, magnitude) = span_and_magnitude(&scaled);
    let too_fine = Tolerance::new(eps).resolve(span, magnitude).is_err();
    let ex = YinSet3::from_triangles(exact_pts, faces.clone());
    let fl = YinSet3::from_triangles_with(float_pts, faces, Tolerance::new(eps));
    match (ex, fl) {
        (_, Err(Yin3Error::ToleranceTooFine { .. })) if too_fine => None,
        (_, Err(e @ Yin3Error::ToleranceTooFine { .. })) => fail!(
            input,
            "operand {name}: float mode refuses ε = {eps:e} ({e}), but its grid carries coordinates up to {magnitude:e}"
        ),
        (_, Ok(_)) if too_fine => fail!(
            input,
            "operand {name}: float mode accepts ε = {eps:e}, too fine for coordinates up to {magnitude:e}"
        ),
        (Err(_), Err(_)) => None,
        // A vertex that the conforming boundary adds is rounded like a result's.
        (Ok(_), Err(Yin3Error::Unrepresentable(_))) => None,
        (Ok(e), Err(err)) => fail!(
            input,
            "operand {name}: exact mode accepts its f64 values, float mode rejects them: {err:?}\nexact: {}",
            show3(&e)
        ),
        (Err(err), Ok(f)) => fail!(
            input,
            "operand {name}: float mode accepts f64 values that exact mode rejects ({err})\nfloat: {}",
            show3(&f)
        ),
        (Ok(e), Ok(f)) => {
            if let Err(err) = f.validate() {
                fail!(
                    input,
                    "operand {name}: the float set fails the validator: {err}\n{}",
                    show3(&f)
                );
            }
            match exact_of(&f, s) {
                Ok(x) if x == e => {}
                Ok(x) => fail!(
                    input,
                    "operand {name}: the float set's values are not the exact set of the values given\nfloat: {}\nexact: {}",
                    show3(&x),
                    show3(&e)
                ),
                Err(err) => fail!(
                    input,
                    "operand {name}: the float set's values do not build a valid set: {err}\n{}",
                    show3(&f)
                ),
            }
            Some(Both { exact: e, float: f })
        }
    }
}

/// vol(x △ y), exactly: |x| + |y| − 2|x ∧ y| for bounded sets, the same on the complements
/// for unbounded ones; `None` if one is bounded and the other not.
fn symmetric_difference_volume(x: &Y3, y: &Y3) -> Option<Rational> {
    if x == y {
        return Some(Rational::from_i64(0));
    }
    if x.is_bounded() != y.is_bounded() {
        return None;
    }
    let (p, q) = if x.is_bounded() {
        (x.clone(), y.clone())
    } else {
        (x.complement(), y.complement())
    };
    let m = p.meet(&q);
    Some(p.volume()? + q.volume()? - Rational::from_i64(2) * m.volume()?)
}

/// Float `locate` against exact `locate` at the probes: where float mode locates a probe inside
/// or outside (farther than ε from the boundary), exact mode must agree on the exact result;
/// within ε float mode says on the boundary, which exact mode need not. For a set rounded once
/// (every vertex moved by at most half an ulp per coordinate, less than any representable ε)
/// a probe on the exact boundary is within ε of the float one, and a probe across it too.
fn check_locate<D: Debug>(name: &str, f: &F3, e: &Y3, fp: &[Point3<Float>], ep: &[P3], input: &D) {
    if fp.is_empty() {
        return;
    }
    let (got, want) = (f.locate(fp), e.locate(ep));
    for k in 0..fp.len() {
        if got[k] != Location::OnBoundary && got[k] != want[k] {
            fail!(
                input,
                "locate: float {name} puts {} {:?}, exact mode {:?} (ε = {:e})\nfloat {name} = {}\nexact {name} = {}",
                ep[k],
                got[k],
                want[k],
                f.ctx().eps(),
                show3(f),
                show3(e)
            );
        }
    }
}

/// 3D float mode against exact mode on the same `f64` values. For each of A∧B, A∨B, A−B, A⊕B
/// and A' (float result F, exact result E of the same operation on the operands' values):
///
/// * each operand: float mode accepts its values iff exact mode does (or refuses ε as too fine
///   exactly when it is), and the float set is valid and is the exact set of its values;
/// * no panic in the `try_` methods, and an error only `Yin3Error::Unrepresentable`;
/// * an Ok F passes `validate()`, and its values read as rationals build a valid exact set Fx
///   independently (`from_triangles`);
/// * Fx and E are both bounded or both unbounded, and vol(Fx △ E) ≤ C·ε·A (C = [`VOLUME_C`], ε
///   the tolerance in force, A the boundary area of both operands and E);
/// * F's Betti numbers are E's (a rounded result keeps the exact result's topology or is
///   Unrepresentable);
/// * float `locate` agrees with exact `locate` at the probes wherever it does not report the
///   boundary, on both operands and on every result.
pub fn ops3_float(input: &Ops3Input) {
    let rotate = input.flags & ROTATE != 0;
    let place = &input.place;
    let s = place.exponent();
    let a = build_operand(&input.a, rotate, input);
    let b = build_operand(&input.b, rotate, input);
    let Some(fa) = operand("A", &a, false, place, input) else {
        return;
    };
    // Rotated operands keep B on the rotated lattice (module docs).
    let Some(fb) = operand("B", &b, !rotate, place, input) else {
        return;
    };
    let (ea, eb) = (&fa.exact, &fb.exact);
    let down = 2f64.powi(-s);
    // ε in force (unscaled): the operands' tolerances combined as the operations combine them.
    let eps = fa.float.ctx().eps().max(fb.float.ctx().eps()) * down;
    // The probes: exact lattice points (rotated with the rest) to the nearest f64s.
    let probe_f64: Vec<[f64; 3]> = input
        .probes
        .iter()
        .map(|p| probe_point(p, rotate).to_f64())
        .collect();
    let ep: Vec<P3> = probe_f64
        .iter()
        .map(|v| Point3::new(exact(v[0]), exact(v[1]), exact(v[2])))
        .collect();
    let up = 2f64.powi(s);
    let fp: Vec<Point3<Float>> = probe_f64
        .iter()
        .map(|v| {
            Point3::new(
                Float::new(v[0] * up),
                Float::new(v[1] * up),
                Float::new(v[2] * up),
            )
        })
        .collect();
    check_locate("A", &fa.float, ea, &fp, &ep, input);
    check_locate("B", &fb.float, eb, &fp, &ep, input);
    let operand_area = ea.boundary_area() + eb.boundary_area();
    for op in OPS {
        let f = match op.try_float(&fa.float, &fb.float) {
            Ok(f) => f,
            Err(Yin3Error::Unrepresentable(_)) => continue,
            Err(err) => fail!(
                input,
                "{op}: float mode fails with {err:?} (only Unrepresentable is allowed)\nA = {}\nB = {}",
                show3(&fa.float),
                show3(&fb.float)
            ),
        };
        if let Err(err) = f.validate() {
            fail!(
                input,
                "{op}: the float result fails the validator: {err}\n{op} = {}",
                show3(&f)
            );
        }
        // Only now (exact A⊕B can take a second on rounded rotated operands).
        let e = op.apply(ea, eb);
        let fx = exact_of(&f, s).unwrap_or_else(|err| {
            fail!(
                input,
                "{op}: the float result's values do not build a valid exact set: {err}\n{op} = {}",
                show3(&f)
            )
        });
        let gap = symmetric_difference_volume(&fx, &e).unwrap_or_else(|| {
            fail!(
                input,
                "{op}: float result {} but exact result {}\nfloat {op} = {}\nexact {op} = {}",
                if fx.is_bounded() {
                    "bounded"
                } else {
                    "unbounded"
                },
                if e.is_bounded() {
                    "bounded"
                } else {
                    "unbounded"
                },
                show3(&fx),
                show3(&e)
            )
        });
        let area = operand_area + e.boundary_area();
        let bound = VOLUME_C * eps * area;
        let within = if area > 0.0 && eps > 0.0 {
            gap.to_f64() <= bound
        } else {
            gap.sign() == Ordering::Equal
        };
        if !within {
            fail!(
                input,
                "{op}: vol(F △ E) = {:e} exceeds {VOLUME_C}·ε·A = {bound:e} (ε = {eps:e}, A = {area:e}, unscaled)\nfloat {op} = {}\nexact {op} = {}",
                gap.to_f64(),
                show3(&fx),
                show3(&e)
            );
        }
        // The set's and its complement's (rounding that makes pieces touch changes only the
        // complement's).
        let (fc, ec) = (f.complement(), e.complement());
        if (f.betti(), fc.betti()) != (e.betti(), ec.betti()) {
            fail!(
                input,
                "{op}: Betti numbers {:?}, complement {:?} ≠ exact {:?}, complement {:?}\nfloat {op} = {}\nexact {op} = {}",
                f.betti(),
                fc.betti(),
                e.betti(),
                ec.betti(),
                show3(&fx),
                show3(&e)
            );
        }
        check_locate(&op.to_string(), &f, &e, &fp, &ep, input);
    }
}

#[cfg(test)]
mod tests {
    /// ops3_float, 2026-11-27: A the complement of a rotated unit box, B a rotated
    /// tetrahedron, both rounded and scaled by 2⁶; float A ∨ B returned `Ok` with Betti numbers
    /// (1, 1, 1) where the exact join has (1, 0, 2): the two pieces of A' ∧ B', apart by less
    /// than an ulp, touched when rounded, and the topology check compared the pieces but not
    /// their complement. Float mode must keep both or refuse (`Unrepresentable`). The input is
    /// the seed that examples/gen_seeds.rs writes from it.
    #[test]
    fn float_join_of_a_box_complement_and_a_tetrahedron_keeps_its_topology() {
        let bytes = include_bytes!("../seeds/ops3/found_pieces_rounded_to_touch");
        super::ops3_float(&crate::input::decode(bytes).expect("decodes"));
    }
}
