//! The 3D Yin space (seeds 003, 004): boundary representations by oriented triangles
//! partitioned into glued surfaces, and the Boolean algebra on them, on the same number trait
//! and kernel as [`crate::yin2`].
//!
//! # Data model
//!
//! A [`YinSet3`] is 0̂, 1̂ or a boundary representation (seed 000 Def. 3.19 in 3D): exact
//! vertices and oriented triangles forming a *conforming* complex — two triangles share
//! nothing, one vertex or one whole edge — with every normal pointing out of the set (seed 003
//! Def. 4.4, 7.3). The triangles are partitioned into glued surfaces (Def. 7.1), each with a
//! sign (Def. 7.3); glued surfaces may share edges and vertices (almost disjoint, Def. 7.2). The
//! Hasse diagram is the inclusion of the surfaces' bounded complements (Def. 7.5, 7.6); an
//! atom is a positive surface with the negative ones it covers, plus at most one atom of
//! negative surfaces alone (Thm 7.10, Cor. 7.11; seed 000 Lemma 3.18 in 2D).
//!
//! The invariants that [`YinSet3::validate`] checks, named in the code as I1–I5:
//!
//! * **I1** the complex is conforming and has no degenerate triangle;
//! * **I2** no two triangles overlap in an area;
//! * **I3** every edge has an even number of faces (fins) whose directions alternate around it
//!   (seed 003 Lemma 5.5(c));
//! * **I4** the winding number on the side each normal points to is 0 (bounded set) or −1
//!   (unbounded set);
//! * **I5** the partition into glued surfaces is the one of Def. 7.8 (unique, Lemma 7.9).
//!
//! Triangulations are not unique, so `==` and `Hash` compare a canonical form: for each plane
//! (its primitive equation and side), the 2D Yin set of that plane's triangles in its chart.
//! The oriented 2-chain ∂𝒴 determines 𝒴.
//!
//! # Algorithms
//!
//! * **Primitives** (kernel and `geom`): a segment meets a plane at
//!   p = a + (b − a)·s_a/(s_a − s_b), s the exact 3D orientation; a plane's 2D chart drops the
//!   axis of the normal's largest component (its sign gives the handedness), so the 2D
//!   predicates of [`crate::kernel`] decide inside it.
//! * **Validation** (`from_triangles`): degenerate faces are rejected and planar n-gons
//!   triangulated; a complex whose triangles meet only in shared corners and edges is its own
//!   arrangement (decided on `f64` values where the coordinates are `f64`s or, scaled, integers
//!   of a common grid below 2⁵³, else on filtered rational orientations); otherwise the
//!   arrangement of the set against itself makes legal contacts (T-junctions, a vertex or an
//!   edge on a face) conforming; then I2, I3 (an odd fin count means an open surface,
//!   non-alternating fins crossing sheets) and I4 (one ray per edge-connected component) are
//!   checked. Errors name the face or edge.
//! * **Triangle–triangle** (seed 004 step 1): box pairs by sweep and prune. A meet's pairs are
//!   first classified from exact orientations of the input vertices as the transversal meet
//!   does (*How the exact result is found* below; also an edge on the other's plane, decided in
//!   that plane against the edge's third corner), and coplanar pairs by orientations of their
//!   corners' images in the plane's chart (corners in the other, edges crossing), each end
//!   named and constructed once; every other pair by the signs of each triangle's corners
//!   against the other's plane and the overlap of the two clipped intervals on the planes'
//!   line. Every contact point is tagged with the feature it lies on in both triangles.
//! * **Re-triangulation** (seed 004 step 2): each cut triangle with its contact points and
//!   constraint segments is triangulated exactly in its chart (orientations only, no Delaunay;
//!   where the segments bound faces with its sides, each face is ear-clipped, no point inserted);
//!   a point on an edge goes into every triangle on that edge (a point named inside an edge is
//!   placed on it by its name, others by exact orientations), and coplanar triangles of both
//!   operands get identical pieces.
//! * **Selection** (seed 000 Lemma 4.6, Cor. 4.7, Def. 4.8, MRS-b..d in 3D): a piece of A
//!   coincident with a piece of B of the same orientation is kept once, of opposite orientation
//!   dropped with it; any other piece is kept iff it lies in the other operand. A piece lies on
//!   the other boundary iff its corners lie in a triangle overlapping its parent in their plane
//!   (orientations in the parent's chart, nothing constructed). Membership is constant on
//!   patches: pieces joined across edges that are no edge of the other operand's pieces (every
//!   contact point goes to every triangle containing it, so an edge on the other boundary is
//!   one of its pieces' edges too), so one ray per patch, from an input vertex where the patch
//!   has one, decides it.
//! * **Rotation order around an edge** (seed 004 "pasting"; seed 003 Def. 5.12, Lemma 5.13):
//!   the fins of an edge (a, b) are sorted by the exact orientation of (b − a, u_f, u_g), u_f
//!   the fin's apex minus a, a fin in the reference fin's plane placed at 0 or π by the side of
//!   the edge it lies on there (an orientation in a coordinate plane); no angles. A fin's
//!   partner in the set is the next fin on the side opposite its normal (the good pairing that
//!   bounds the set locally), its partner outside the next on its normal's side; coinciding
//!   fins are an overlap.
//! * **Glued surfaces** (seed 003 Def. 7.8): triangles are joined only across paired fins,
//!   never through a vertex; union–find across partners in the set gives the pre-surfaces, and
//!   inside each, at edges where it owns more than two fins, its own fins are paired by the
//!   outside partner in their restricted order, which gives the glued surfaces.
//! * **Orientation, boundedness, Hasse diagram**: a surface's signed volume
//!   Σ det(p0 − o, p1 − o, p2 − o)/6 gives its sign (Def. 7.3); the set is bounded iff the total
//!   is positive; S_l lies inside S_k iff |V_l| < |V_k| and a point of S_l off S_k has a non-zero
//!   winding number about S_k.
//! * **Complement** (seed 000 Def. 4.4): 0̂ and 1̂ swap; otherwise every triangle is reversed
//!   and the surfaces and Hasse diagram are rebuilt, since surfaces regroup.
//! * **Meet**: triangle–triangle, re-triangulation, selection, glued surfaces and the Hasse
//!   diagram in turn, with shortcuts for 0̂, 1̂ and disjoint boxes. Join by De Morgan (Def. 4.10).
//!   Exact operands are met by float mode's construction-light meet (*Float mode*, *How the
//!   exact result is found*) wherever it applies: where their coordinates, times one integer L
//!   (the lcm of their denominators), are integers below 2⁵³ — decimal files of a few places,
//!   lattices — scaled to that grid, its vertices divided by L; otherwise on their rationals,
//!   with the same tests on filtered rational orientations and each pierce point constructed
//!   on the integers of its five corners over their common denominator.
//! * **Locate**: a point is on the boundary iff it lies in a closed triangle; otherwise the ray
//!   q + t(1, 0, 0), t > 0, symbolically perturbed to q + (0, ε, ε²), counts the signs of the
//!   normals' x components of the triangles it crosses (a tie on a projected edge a → b takes
//!   the sign of −(b_z − a_z), then of b_y − a_y; triangles parallel to the ray never count);
//!   the point is inside iff that count plus \[unbounded\] is 1. Deterministic and exact.
//! * **Betti numbers** of the open set (over ℚ): b0 = the number of atoms; b2 = the bounded
//!   components of the closed complement (Alexander duality: atoms of the complement that share
//!   a vertex are one class); χ from the vertex links, χ(∂𝒴 pushed into 𝒴) = Σ_p (2r_p − l_p) − F/2
//!   with F the triangles, l_p the corner cycles at p (corners joined across partners in the
//!   set) and r_p the local components of the set at p (r_p = l_p where the link is connected;
//!   otherwise the link's components are nested by exact crossings of their cones); then
//!   χ(𝒴) = χ(∂𝒴 pushed in)/2 + \[unbounded\] and b1 = b0 + b2 − χ. A solid torus is (1, 1, 0),
//!   two cubes sharing an edge (2, 0, 0), the complement of a ball (1, 0, 1).
//! * **Volume**: Σ det/6 over the triangles, `None` when unbounded.
//!
//! # Float mode
//!
//! `YinSet3<Float>` takes `f64` vertices and a [`crate::num::Tolerance`], as in 2D;
//! [`YinSet3::try_meet`], [`YinSet3::try_join`], [`YinSet3::try_difference`] and
//! [`YinSet3::try_symmetric_difference`] return a [`Yin3Error`] where the operators would panic.
//! The contract (tests/float_mode3.rs checks every clause):
//!
//! * **Exact topology, rounded vertices.** An operation is computed exactly on the operands'
//!   `f64` values (read as rationals, scaled by one power of two to integers), and each vertex
//!   of the exact result is rounded to the nearest `f64`s — once: ⊕ too is one exact operation.
//!   Points rounding to one point are merged and triangles collapsing to a segment dropped. The
//!   rounded boundary is returned only if it passes the exact validator and keeps the exact
//!   result's topology and its complement's: boundedness, Betti numbers, and each glued
//!   surface's orientation, genus and depth in the Hasse diagram. (Two pieces closer than an ulp
//!   can round to pieces that touch: still the same surfaces, but their complement's cavities
//!   merge.) A sufficient test settles this without the exact structure (the fins of every
//!   edge turn about it in the exact order — always, with two fins —, each glued surface's
//!   signed volume, the set's and, where an edge has more fins, the complement's, is farther
//!   from 0 than rounding can move it, two surfaces within rounding of each other each have a
//!   vertex farther than twice the rounding from the other, and at vertices where pieces touch
//!   the link's faces in the set are the same; with more than two fins at an edge the windings
//!   are checked by rays) where no point merged, or where each merge of two points is the
//!   collapse of an edge of one surface that keeps its type (the link condition), away from
//!   the other merges and from where pieces touch, with two fins at every edge; otherwise both
//!   topologies are computed and compared. Failing that, the
//!   operation returns `Yin3Error::Unrepresentable` — never an invalid set, never a panic in the
//!   `try_` methods — e.g. for a sliver thinner than an ulp, which rounding would turn inside
//!   out.
//! * **How the exact result is found.** When every pair of triangles of the two operands
//!   misses, crosses properly, crosses edge through edge, from a shared corner or from a vertex
//!   inside the other's triangle, or touches in a shared corner or edge or at such a vertex, the
//!   meet is decided from exact orientations of the input vertices alone (the `f64` values of
//!   float sets; in exact mode the same tests on filtered rational orientations): each end of a
//!   crossing segment is named by what defines it (an edge and the triangle it pierces, two
//!   crossing edges, a vertex in a triangle, a shared corner) and constructed once, a pierce
//!   point on 256- or 384-bit stack integers where the corners on their common power-of-two
//!   grid fit in 62 or 94 bits, on big integers beyond. Membership flips across every crossing
//!   segment and stays across every other unshared edge, so one ray per connected surface, and
//!   one per patch that only shared edges bound, decides every patch. Boundaries that do not
//!   meet are decided by one ray per glued surface (an operand inside the other is returned as
//!   it is, nothing to round); boundaries that only touch in shared corners and edges by one
//!   ray per patch, nothing constructed. At the first coplanar overlap, edge in the other's
//!   plane or vertex on an edge of the other, the meet takes the general exact arrangement.
//!   There every pair is settled and named this way: besides the kinds above, every pair with
//!   a vertex on the other's plane — an edge in that plane, a vertex on an edge of the other,
//!   an edge through the other's corner, beside a shared corner or not — by the ends of each
//!   triangle's meet with the planes' line that lie in the other, and every coplanar pair (its
//!   common polygon's corners: corners of either in the other, and edges crossing,
//!   constructed where one edge pierces the plane through the other along the chart's dropped
//!   axis). A pair neither settles (a degenerate triangle, which valid operands do not have)
//!   constructs its contact.
//!   Where rounding moved vertices, the triangles at moved vertices are checked against their
//!   neighbours by the validator's own tests, and the whole result validated where those
//!   cannot tell; a result whose vertices are all `f64`s already is the exact one.
//! * **Validity.** Faces given to [`YinSet3::from_triangles_with`] are validated exactly, so
//!   every float set is an exactly valid Yin set of its values; `validate()` checks exactly;
//!   `==` and `Hash` are equality of the exact values.
//! * **ε.** `locate` reports a point within distance ε of a face as on the boundary and locates
//!   every other point exactly. The default ε and the representable ε are 2D's (10⁻¹⁰ × the
//!   bounding box's larger side, rounded down to a power of two; a finer ε than the coordinates
//!   carry is `Yin3Error::ToleranceTooFine`). ε does not move results: rounding moves each
//!   vertex by at most half an ulp per coordinate, below the finest representable ε, so
//!   vol(F △ E) ≤ C·ε·A with C = 1, A the boundary area of the operands plus E's (measured, as
//!   tests/float_mode3.rs prints with `--nocapture`).
//! * **Range.** Coordinates from 10⁻³⁰⁰ to 10³⁰⁰ work: orientation is exact at any magnitude (a
//!   static filter, then 128-bit integers where the coordinates are integers below 2⁶⁰ on one
//!   power-of-two grid, then Shewchuk's adaptive `orient3d` after an exact power-of-two scaling,
//!   rationals where even that under- or overflows).
//! * **Speed.** Exact mode takes the same construction-light meet as float mode wherever
//!   operands cross, touch only in shared corners and edges, or do not meet (*Meet*), so the
//!   two modes take about the same time there on the crossing spheres and meshes of
//!   benches/BENCHMARKS.md (float 0.46–1.31× exact), float mode paying for its rounding check;
//!   where operands share faces or meet otherwise degenerately float mode takes the general
//!   arrangement on its values and rounds the pieces it keeps, at 0.92–2.05× exact mode's
//!   time.

mod arrange;
mod betti;
mod bvh;
mod canonical;
mod complement;
mod contact;
mod corners;
mod error;
mod fins;
mod float;
mod geom;
mod glue;
mod grid;
mod hasse;
mod in_plane;
mod input;
mod kept;
mod link;
mod locate;
mod meet;
mod named;
mod near;
mod ops;
mod parallel;
mod pierce;
mod set;
pub mod shapes;
mod soup;
mod star;
mod sweep;
mod transversal;
mod tri;
mod triangulate;
mod validate;
mod values;

pub use betti::Betti3;
pub use error::{Spot, Yin3Error};
pub use hasse::Atom3;
pub use set::{GluedSurface, YinSet3};
