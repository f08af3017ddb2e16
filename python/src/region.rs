//! `Region2`: a 2D Yin set, exact (`YinSet2<Rational>`) or float (`YinSet2<Float>` with its
//! tolerance), with the Boolean algebra, measures, location and the OGC formats.

use crate::bytes::{float_bytes, floats, location_codes, measure, points2, Measure};
use crate::error;
use crate::mode::{all_in, map, on, Modal};
use pyo3::prelude::*;
use pyo3::types::PyBytes;
use std::hash::{Hash, Hasher};
use yinset::io::yin2_text::{self, Yin2Text};
use yinset::io::{self, geojson, wkb, wkt, NumberStyle, Polygon};
use yinset::num::{Float, Num, Rational};
use yinset::yin2::{FillRule, YinSet2};

/// A 2D Yin set in either mode (float: `f64` on the grid of ε).
type Set2 = Modal<YinSet2<Rational>, YinSet2<Float>>;

/// A 2D Yin set (regular open semianalytic subset of the plane), exact or float.
#[pyclass(frozen, module = "yinset._yinset")]
#[derive(Clone)]
pub struct Region2(Set2);

/// The fill rule named `fill` (None: the rings are a Yin set's boundary, validated).
fn fill_rule(fill: Option<&str>) -> PyResult<Option<FillRule>> {
    match fill {
        None => Ok(None),
        Some("nonzero") => Ok(Some(FillRule::NonZero)),
        Some("evenodd") => Ok(Some(FillRule::EvenOdd)),
        Some(other) => Err(error(format!(
            "fill = {other:?}: the fill rule is \"nonzero\" or \"evenodd\""
        ))),
    }
}

/// The rings of `xy` (consecutive points, `lengths` of them per ring) as points of `N`.
fn rings_of<N: Num>(xy: &[f64], lengths: &[usize]) -> PyResult<Vec<Vec<yinset::kernel::Point<N>>>> {
    if lengths.iter().sum::<usize>() * 2 != xy.len() {
        return Err(error("ring lengths do not add up to the number of points"));
    }
    let mut start = 0;
    lengths
        .iter()
        .enumerate()
        .map(|(r, &n)| {
            let ring = &xy[2 * start..2 * (start + n)];
            start += n;
            points2(ring, |k| format!("ring {r}, point {k}"))
        })
        .collect()
}

/// The set bounded by `rings` (or filled by them under `fill`) with context `ctx`.
fn build<N: Num>(
    rings: Vec<Vec<yinset::kernel::Point<N>>>,
    fill: Option<FillRule>,
    ctx: N::Ctx,
) -> PyResult<YinSet2<N>> {
    if rings.is_empty() {
        return Ok(YinSet2::empty().with_ctx(ctx));
    }
    match fill {
        None => YinSet2::from_curves_with(rings, ctx),
        Some(rule) => YinSet2::from_rings_filled_with(rings, rule, ctx),
    }
    .map_err(error)
}

/// The set of OGC `polygons`: exteriors counterclockwise, holes clockwise (or filled).
fn of_polygons<N: Num>(
    polygons: Vec<Polygon<N>>,
    fill: Option<FillRule>,
    ctx: N::Ctx,
) -> PyResult<YinSet2<N>> {
    let rings = polygons
        .into_iter()
        .flat_map(|p| p.oriented_rings().map(|(_, ring, _)| ring))
        .collect();
    build(rings, fill, ctx)
}

/// Which OGC format a text or buffer is in.
#[derive(Clone, Copy)]
enum Ogc {
    Wkt,
    Wkb,
    Geojson,
}

/// The polygons of `data` in `format` (WKB as raw bytes or hex digits).
fn read_ogc<N: Num>(data: &[u8], format: Ogc) -> PyResult<Vec<Polygon<N>>> {
    let text = || std::str::from_utf8(data).map_err(|e| error(format!("not UTF-8 text: {e}")));
    match format {
        Ogc::Wkt => wkt::read_polygons(text()?).map_err(error),
        Ogc::Geojson => geojson::read_polygons(text()?).map_err(error),
        Ogc::Wkb if wkb::is_hex(data) => {
            wkb::read_polygons(&wkb::from_hex(text()?).map_err(error)?).map_err(error)
        }
        Ogc::Wkb => wkb::read_polygons(data).map_err(error),
    }
}

/// The set of the yin2 curve list `text` (curves as given, interior on the left; `plane`: 1̂).
fn of_yin2<N: Num>(text: &str, ctx: N::Ctx) -> PyResult<YinSet2<N>> {
    match yin2_text::read(text).map_err(error)? {
        Yin2Text::Plane => Ok(YinSet2::full().with_ctx(ctx)),
        Yin2Text::Curves(curves) => build(curves, None, ctx),
    }
}

impl Region2 {
    /// The region `op(self, other)`, computed without the GIL; both must be in the same mode.
    fn binary(
        &self,
        py: Python<'_>,
        other: &Region2,
        exact: fn(&YinSet2<Rational>, &YinSet2<Rational>) -> YinSet2<Rational>,
        float: fn(&YinSet2<Float>, &YinSet2<Float>) -> YinSet2<Float>,
    ) -> PyResult<Region2> {
        self.0
            .pair(
                &other.0,
                |a, b| Ok(py.detach(|| exact(a, b))),
                |a, b| Ok(py.detach(|| float(a, b))),
            )
            .map(Region2)
    }

    /// The polygons of the set, for an OGC writer (`format` names it if the set is unbounded).
    fn polygons<N: Num>(set: &YinSet2<N>, format: &str) -> PyResult<Vec<Polygon<N>>> {
        io::polygons_of(set).ok_or_else(|| {
            error(format!(
                "the region is unbounded, and {format} holds bounded polygons only"
            ))
        })
    }
}

/// The number style of the OGC writers: exact digits (`p/q` where needed) or shortest decimals.
fn style(exact: bool) -> NumberStyle {
    if exact {
        NumberStyle::Exact
    } else {
        NumberStyle::Decimal
    }
}

#[pymethods]
impl Region2 {
    /// The region bounded by rings `xy` (little-endian f64 pairs, `lengths` points per ring),
    /// or filled by them under `fill`; exact if `eps` is None.
    #[staticmethod]
    #[pyo3(signature = (xy, lengths, eps=None, fill=None))]
    fn from_rings(
        py: Python<'_>,
        xy: &[u8],
        lengths: Vec<usize>,
        eps: Option<f64>,
        fill: Option<&str>,
    ) -> PyResult<Region2> {
        let xy = floats(xy, 2)?;
        let fill = fill_rule(fill)?;
        py.detach(|| {
            Modal::new_in(
                eps,
                || build(rings_of(&xy, &lengths)?, fill, ()),
                |t| build(rings_of(&xy, &lengths)?, fill, t),
            )
            .map(Region2)
        })
    }

    /// The region of OGC polygons in `data`: `format` is "wkt", "wkb" (bytes or hex) or
    /// "geojson".
    #[staticmethod]
    #[pyo3(signature = (data, format, eps=None, fill=None))]
    fn from_ogc(
        py: Python<'_>,
        data: &[u8],
        format: &str,
        eps: Option<f64>,
        fill: Option<&str>,
    ) -> PyResult<Region2> {
        let format = match format {
            "wkt" => Ogc::Wkt,
            "wkb" => Ogc::Wkb,
            "geojson" => Ogc::Geojson,
            other => return Err(error(format!("unknown 2D format {other:?}"))),
        };
        let fill = fill_rule(fill)?;
        py.detach(|| {
            Modal::new_in(
                eps,
                || of_polygons(read_ogc(data, format)?, fill, ()),
                |t| of_polygons(read_ogc(data, format)?, fill, t),
            )
            .map(Region2)
        })
    }

    /// The region of a yin2 text: curves of `x y` lines separated by blank lines.
    #[staticmethod]
    #[pyo3(signature = (text, eps=None))]
    fn from_yin2(py: Python<'_>, text: &str, eps: Option<f64>) -> PyResult<Region2> {
        py.detach(|| Modal::new_in(eps, || of_yin2(text, ()), |t| of_yin2(text, t)).map(Region2))
    }

    /// The empty region 0̂.
    #[staticmethod]
    #[pyo3(signature = (eps=None))]
    fn empty(eps: Option<f64>) -> PyResult<Region2> {
        Modal::new_in(
            eps,
            || Ok(YinSet2::empty()),
            |t| Ok(YinSet2::empty().with_ctx(t)),
        )
        .map(Region2)
    }

    /// The whole plane 1̂.
    #[staticmethod]
    #[pyo3(signature = (eps=None))]
    fn full(eps: Option<f64>) -> PyResult<Region2> {
        Modal::new_in(
            eps,
            || Ok(YinSet2::full()),
            |t| Ok(YinSet2::full().with_ctx(t)),
        )
        .map(Region2)
    }

    /// True in exact mode.
    #[getter]
    fn exact(&self) -> bool {
        matches!(self.0, Set2::Exact(_))
    }

    /// The tolerance ε in float mode (None in exact mode).
    #[getter]
    fn eps(&self) -> Option<f64> {
        match &self.0 {
            Set2::Exact(_) => None,
            Set2::Float(s) => Some(s.ctx().eps()),
        }
    }

    /// A ∧ B.
    fn meet(&self, py: Python<'_>, other: &Region2) -> PyResult<Region2> {
        self.binary(py, other, YinSet2::meet, YinSet2::meet)
    }

    /// A ∨ B.
    fn join(&self, py: Python<'_>, other: &Region2) -> PyResult<Region2> {
        self.binary(py, other, YinSet2::join, YinSet2::join)
    }

    /// A ∧ B′.
    fn difference(&self, py: Python<'_>, other: &Region2) -> PyResult<Region2> {
        self.binary(py, other, YinSet2::difference, YinSet2::difference)
    }

    /// (A ∧ B′) ∨ (A′ ∧ B).
    fn symmetric_difference(&self, py: Python<'_>, other: &Region2) -> PyResult<Region2> {
        self.binary(
            py,
            other,
            YinSet2::symmetric_difference,
            YinSet2::symmetric_difference,
        )
    }

    /// A′.
    fn complement(&self, py: Python<'_>) -> Region2 {
        Region2(py.detach(|| map!(&self.0, s => s.complement())))
    }

    /// A ∧ C for each cell C of `cells` (in parallel).
    fn meet_each(&self, py: Python<'_>, cells: Vec<PyRef<'_, Region2>>) -> PyResult<Vec<Region2>> {
        let cells: Vec<&Set2> = cells.iter().map(|c| &c.0).collect();
        let parts: Vec<Set2> = match &self.0 {
            Set2::Exact(a) => {
                let cells = all_in(cells, Modal::exact)?;
                py.detach(|| a.meet_each(&cells))
                    .into_iter()
                    .map(Set2::Exact)
                    .collect()
            }
            Set2::Float(a) => {
                let cells = all_in(cells, Modal::float)?;
                py.detach(|| a.meet_each(&cells))
                    .into_iter()
                    .map(Set2::Float)
                    .collect()
            }
        };
        Ok(parts.into_iter().map(Region2).collect())
    }

    /// Set equality (the same open set); false across modes.
    fn equals(&self, other: &Region2) -> bool {
        match (&self.0, &other.0) {
            (Set2::Exact(a), Set2::Exact(b)) => a == b,
            (Set2::Float(a), Set2::Float(b)) => a == b,
            _ => false,
        }
    }

    /// ρ(A) ⊆ ρ(B).
    fn is_subset(&self, py: Python<'_>, other: &Region2) -> PyResult<bool> {
        self.0
            .pair(
                &other.0,
                |a, b| Ok(py.detach(|| a.is_subset(b))),
                |a, b| Ok(py.detach(|| a.is_subset(b))),
            )
            .map(Modal::value)
    }

    /// A hash consistent with `equals`.
    fn hash(&self) -> u64 {
        let mut h = std::collections::hash_map::DefaultHasher::new();
        on!(&self.0, s => s.hash(&mut h));
        h.finish()
    }

    /// True for 0̂.
    fn is_empty(&self) -> bool {
        on!(&self.0, s => s.is_empty())
    }

    /// True for 1̂.
    fn is_full(&self) -> bool {
        on!(&self.0, s => s.is_full())
    }

    /// True if the closure is compact.
    fn is_bounded(&self) -> bool {
        on!(&self.0, s => s.is_bounded())
    }

    /// The area: exact (numerator, denominator) texts in exact mode, the f64 in float mode;
    /// None if unbounded.
    fn area(&self) -> Option<Measure> {
        on!(&self.0, s => measure(s.area()))
    }

    /// The seed's Betti numbers: (components, holes).
    fn betti(&self) -> (usize, usize) {
        let b = on!(&self.0, s => s.betti());
        (b.components, b.total_holes)
    }

    /// The homological Betti numbers (b0, b1).
    fn homology(&self, py: Python<'_>) -> (usize, usize) {
        let h = py.detach(|| on!(&self.0, s => s.homology()));
        (h.b0, h.b1)
    }

    /// The location codes (as i8 bytes) of the points `xy` (little-endian f64 pairs).
    fn locate<'py>(&self, py: Python<'py>, xy: &[u8]) -> PyResult<Bound<'py, PyBytes>> {
        let xy = floats(xy, 2)?;
        let codes = py.detach(|| -> PyResult<Vec<u8>> {
            on!(&self.0, s => {
                let points = points2(&xy, |k| format!("point {k}"))?;
                Ok(location_codes(&s.locate(&points)))
            })
        })?;
        Ok(PyBytes::new(py, &codes))
    }

    /// Check the stored boundary (the kernel's validator); raises YinsetError if invalid.
    fn validate(&self, py: Python<'_>) -> PyResult<()> {
        py.detach(|| on!(&self.0, s => s.validate())).map_err(error)
    }

    /// The boundary curves as (f64 bytes of their vertices, each nearest to the exact one;
    /// count) pairs, interior on the left.
    fn curves<'py>(&self, py: Python<'py>) -> Vec<(Bound<'py, PyBytes>, usize)> {
        on!(&self.0, s => s
            .curves()
            .iter()
            .map(|c| {
                let v = c.vertices();
                let xy = float_bytes(v.iter().flat_map(|p| [&p.x, &p.y]));
                (PyBytes::new(py, &xy), v.len())
            })
            .collect())
    }

    /// WKT of the bounded region (exact digits, `p/q` where needed, if `exact`).
    #[pyo3(signature = (exact=false))]
    fn to_wkt(&self, exact: bool) -> PyResult<String> {
        on!(&self.0, s => wkt::write_multipolygon(&Region2::polygons(s, "WKT")?, style(exact)))
            .map_err(error)
    }

    /// GeoJSON geometry of the bounded region.
    fn to_geojson(&self) -> PyResult<String> {
        on!(&self.0, s => geojson::write_multipolygon(
            &Region2::polygons(s, "GeoJSON")?,
            NumberStyle::Decimal
        ))
        .map_err(error)
    }

    /// Little-endian WKB of the bounded region (coordinates the nearest f64s).
    fn to_wkb<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyBytes>> {
        let bytes = on!(&self.0, s => wkb::write_multipolygon(
            &Region2::polygons(s, "WKB")?,
            NumberStyle::Decimal
        ))
        .map_err(error)?;
        Ok(PyBytes::new(py, &bytes))
    }
}
