//! 3D Boolean operations on the meshes of ../shared/data/3d (issue 16 item 6): the contact
//! configurations the data README lists, with exact volume identities, involution, the public
//! validator on every output, and the self-intersecting teddy rejected.

mod common;
use common::data_file_3d;
use yinset::io::obj::read_obj;
use yinset::num::Rational;
use yinset::yin3::{Betti3, Yin3Error, YinSet3};

type Y = YinSet3<Rational>;

/// The Yin set bounded by a mesh of the shared data.
fn load(name: &str) -> Result<Y, Yin3Error> {
    let path = data_file_3d(name);
    let text = std::fs::read_to_string(&path).expect("readable data file");
    let mesh = read_obj::<Rational>(&text).expect("well-formed OBJ");
    YinSet3::from_triangles(mesh.vertices, mesh.faces)
}

fn betti(y: &Y) -> (usize, usize, usize) {
    let Betti3 { b0, b1, b2 } = y.betti();
    (b0, b1, b2)
}

/// Meet, join and both differences of `a` and `b`, each validated, with the exact identities
/// |A∧B| + |A∨B| = |A| + |B| and |A| = |A∧B| + |A∧B'|.
fn operations(a: &Y, b: &Y) -> [Y; 4] {
    let (m, j, d, e) = (a & b, a | b, a - b, b - a);
    for y in [&m, &j, &d, &e] {
        y.validate().expect("every output is a valid Yin set");
    }
    let vol = |y: &Y| y.volume().expect("bounded");
    assert_eq!(vol(&m) + vol(&j), vol(a) + vol(b));
    assert_eq!(vol(a), vol(&m) + vol(&d));
    assert_eq!(vol(b), vol(&m) + vol(&e));
    [m, j, d, e]
}

#[test]
fn balls_touching_at_one_point_join_into_two_components() {
    if !common::data_available() {
        return;
    }
    let (a, b) = (
        load("ballahead.obj").unwrap(),
        load("ballabehind.obj").unwrap(),
    );
    let [m, j, d, _] = operations(&a, &b);
    assert!(m.is_empty(), "they share a single point: the meet is 0̂");
    assert_eq!(betti(&j), (2, 0, 0));
    assert_eq!(j.surfaces().len(), 2);
    assert_eq!(d, a);
    assert_eq!(!&!&j, j);
}

#[test]
fn a_cavity_touching_the_outer_surface_at_one_point() {
    if !common::data_available() {
        return;
    }
    let (mid, left) = (load("ballmid.obj").unwrap(), load("ballleft.obj").unwrap());
    let [m, j, d, e] = operations(&mid, &left);
    assert_eq!(m, left, "ballleft lies inside ballmid");
    assert_eq!(j, mid);
    assert!(e.is_empty());
    // The cavity touches the outside at a point: it is not a bounded component of the
    // closed complement, so b2 = 0 although there is a negatively oriented surface.
    assert_eq!(betti(&d), (1, 0, 0));
    let signs: Vec<bool> = d.surfaces().iter().map(|s| s.positive).collect();
    assert_eq!(signs.iter().filter(|p| **p).count(), 1);
    assert_eq!(signs.len(), 2);
    assert_eq!(!&!&d, d);
}

#[test]
fn a_ball_a_millionth_inside_another_without_contact() {
    if !common::data_available() {
        return;
    }
    let (mid, right) = (load("ballmid.obj").unwrap(), load("ballright.obj").unwrap());
    let [m, j, d, _] = operations(&mid, &right);
    assert_eq!(m, right);
    assert_eq!(j, mid);
    assert_eq!(betti(&d), (1, 0, 1), "a cavity not touching anything");
    assert_eq!(!&!&d, d);
}

#[test]
fn a_ball_inscribed_in_a_torus_tube_cuts_the_handle() {
    if !common::data_available() {
        return;
    }
    let (torus, ball) = (load("torus.obj").unwrap(), load("innerball.obj").unwrap());
    assert_eq!(betti(&torus), (1, 1, 0));
    assert_eq!(torus.surfaces()[0].genus, 1);
    let [m, j, d, e] = operations(&torus, &ball);
    assert_eq!(m, ball, "the data README: torus ∧ innerball = innerball");
    assert_eq!(j, torus);
    assert!(e.is_empty());
    // The ball touches the tube along a closed meridian polygon of 8 shared edges (4-face
    // edges), so removing it cuts the solid torus into a solid cylinder.
    assert_eq!(betti(&d), (1, 0, 0));
    assert_eq!(d.surfaces().len(), 2);
    assert_eq!(!&!&d, d);
}

#[test]
fn teddy_is_rejected_naming_two_crossing_faces() {
    if !common::data_available() {
        return;
    }
    match load("teddy.obj") {
        Err(Yin3Error::Crossing { a, b, .. }) => assert_ne!(a, b),
        other => panic!("teddy.obj intersects itself, yet: {other:?}"),
    }
}

#[test]
fn clean_meshes_of_the_data_are_valid_with_their_genus() {
    if !common::data_available() {
        return;
    }
    for (name, genus) in [
        ("heart.obj", 0),
        ("ballconnecttorus.obj", 1),
        ("Rabbit_Lowpoly_2.obj", 0),
    ] {
        let y = load(name).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(y.surfaces().len(), 1, "{name}");
        assert_eq!(y.surfaces()[0].genus, genus, "{name}");
        assert_eq!(betti(&y), (1, genus, 0), "{name}");
    }
}
