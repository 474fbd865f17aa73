//! The book's examples 2.1–2.6 and the chapter-2 exercises whose text fully
//! specifies the mechanism (§2.7), plus the errors.

use super::*;

fn mech(
    space: &str,
    links: Option<i64>,
    joints: &[(i64, &str)],
    legs: Option<(i64, &str)>,
) -> Mechanism {
    match Mechanism::from_spec(Some(space), links, joints, legs) {
        Ok(m) => m,
        Err(e) => panic!("unexpected error: {e}"),
    }
}

fn err(
    space: Option<&str>,
    links: Option<i64>,
    joints: &[(i64, &str)],
    legs: Option<(i64, &str)>,
) -> MechError {
    match Mechanism::from_spec(space, links, joints, legs) {
        Ok(m) => panic!("expected an error, got\n{m}"),
        Err(e) => e,
    }
}

/// Asserts N, J, Σf, dof and the exact formula.
fn check(m: &Mechanism, n: i64, j: i64, sum_f: i64, dof: i64, formula: &str) {
    assert_eq!(m.links(), n, "N");
    assert_eq!(m.joint_count(), j, "J");
    assert_eq!(m.sum_f(), sum_f, "Σf");
    assert_eq!(m.dof(), dof, "dof");
    assert_eq!(m.formula(), formula);
}

fn has_note(m: &Mechanism, part: &str) -> bool {
    m.notes().iter().any(|n| n.contains(part))
}

const LOWER: &str = "lower bound: constraints may be dependent";

// ---------- Table 2.1 ----------

#[test]
fn table_2_1_freedoms_and_constraints() {
    let rows = [
        (JointType::R, 1, Some(2), 5),
        (JointType::P, 1, Some(2), 5),
        (JointType::H, 1, None, 5),
        (JointType::C, 2, None, 4),
        (JointType::U, 2, None, 4),
        (JointType::S, 3, None, 3),
    ];
    for (t, f, c_planar, c_spatial) in rows {
        assert_eq!(t.freedoms(), f);
        assert_eq!(t.constraints(Space::Planar), c_planar);
        assert_eq!(t.constraints(Space::Spatial), Some(c_spatial));
        assert_eq!(JointType::from_letter(t.letter()), Some(t));
        assert_eq!(
            JointType::from_letter(t.letter().to_ascii_lowercase()),
            Some(t)
        );
    }
    assert_eq!(JointType::from_letter('X'), None);
    assert_eq!(JointType::R.constraints(Space::Spherical), Some(2));
    assert_eq!(JointType::P.constraints(Space::Spherical), None);
    assert_eq!(JointType::ALL.len(), 6);
}

#[test]
fn spaces_and_m() {
    assert_eq!(Space::parse("planar"), Some(Space::Planar));
    assert_eq!(Space::parse(" Spatial "), Some(Space::Spatial));
    assert_eq!(Space::parse("spherical"), Some(Space::Spherical));
    assert_eq!(Space::parse("plane"), None);
    assert_eq!(Space::Planar.m(), 3);
    assert_eq!(Space::Spatial.m(), 6);
    assert_eq!(Space::Spherical.m(), 3);
}

#[test]
fn compound_joint_freedoms_add() {
    let rp = Joint {
        kinds: vec![JointType::R, JointType::P],
    };
    assert_eq!(rp.freedoms(), 2);
    assert_eq!(rp.constraints(Space::Planar), Some(1));
    assert_eq!(rp.letters(), "RP");
}

// ---------- Example 2.1 ----------

#[test]
fn example_2_1_four_bar() {
    let m = mech(
        "planar",
        Some(4),
        &[(1, "R"), (1, "R"), (1, "R"), (1, "R")],
        None,
    );
    check(&m, 4, 4, 4, 1, "dof = 3(4 − 1 − 4) + 4·1 = 1");
    assert_eq!(m.m(), 3);
    assert_eq!(m.joints_text(), "R R R R");
    assert!(m.is_closed_chain());
    assert!(has_note(&m, LOWER));
    assert_eq!(m.topology(), None);
    let m = mech("planar", Some(4), &[(4, "R")], None);
    check(&m, 4, 4, 4, 1, "dof = 3(4 − 1 − 4) + 4·1 = 1");
    assert_eq!(m.joints_text(), "4R");
}

#[test]
fn example_2_1_slider_crank_both_readings() {
    // (i) three R and one P joint, four links.
    let m = mech("planar", Some(4), &[(3, "R"), (1, "P")], None);
    check(&m, 4, 4, 4, 1, "dof = 3(4 − 1 − 4) + 4·1 = 1");
    assert_eq!(m.joints_text(), "3R P");
    // (ii) two R joints and one RP joint (f = 2), three links.
    let m = mech("planar", Some(3), &[(2, "R"), (1, "RP")], None);
    check(&m, 3, 3, 4, 1, "dof = 3(3 − 1 − 3) + 2·1 + 1·2 = 1");
    assert_eq!(m.joints_text(), "2R RP");
}

// ---------- Example 2.2 ----------

#[test]
fn example_2_2_k_link_serial_chain() {
    for k in 1..=12 {
        let m = mech("planar", Some(k + 1), &[(k, "R")], None);
        let f = format!("dof = 3({} − 1 − {k}) + {k}·1 = {k}", k + 1);
        check(&m, k + 1, k, k, k, &f);
        assert!(!m.is_closed_chain());
        assert!(m.notes().is_empty(), "{:?}", m.notes());
        let t = if k == 1 {
            "S^1".to_string()
        } else {
            format!("T^{k}")
        };
        assert_eq!(m.topology(), Some(t));
    }
}

#[test]
fn example_2_2_five_bar_and_six_bars() {
    let m = mech("planar", Some(5), &[(5, "R")], None);
    check(&m, 5, 5, 5, 2, "dof = 3(5 − 1 − 5) + 5·1 = 2");
    // Stephenson and Watt six-bar linkages: same counts.
    let m = mech("planar", Some(6), &[(7, "R")], None);
    check(&m, 6, 7, 7, 1, "dof = 3(6 − 1 − 7) + 7·1 = 1");
    assert!(has_note(&m, LOWER));
}

// ---------- Example 2.3 ----------

#[test]
fn example_2_3_overlapping_joints_both_readings() {
    // (i) eight links, eight R joints and one P joint: the book's "9(1)".
    let m = mech("planar", Some(8), &[(8, "R"), (1, "P")], None);
    check(&m, 8, 9, 9, 3, "dof = 3(8 − 1 − 9) + 9·1 = 3");
    assert_eq!(m.joints_text(), "8R P");
    // (ii) seven links, seven R joints and one RP pair: "7(1) + 1(2)".
    let m = mech("planar", Some(7), &[(7, "R"), (1, "RP")], None);
    check(&m, 7, 8, 9, 3, "dof = 3(7 − 1 − 8) + 7·1 + 1·2 = 3");
    assert_eq!(m.joints_text(), "7R RP");
}

// ---------- Example 2.4 ----------

#[test]
fn example_2_4_parallelogram_is_a_structure_by_the_formula() {
    let m = mech("planar", Some(5), &[(6, "R")], None);
    check(&m, 5, 6, 6, 0, "dof = 3(5 − 1 − 6) + 6·1 = 0");
    assert!(m.is_lower_bound());
    assert!(has_note(&m, "by the formula a structure (dof ≤ 0)"));
    assert!(has_note(&m, LOWER));
}

// ---------- Example 2.5 ----------

#[test]
fn example_2_5_delta_robot_naive_uses_real_m() {
    // The book prints "17(17 − 1 − 21) + 21 = −9": a slip, m is 6.
    let m = mech("spatial", Some(17), &[(21, "R")], None);
    check(&m, 17, 21, 21, -9, "dof = 6(17 − 1 − 21) + 21·1 = −9");
    assert!(has_note(
        &m,
        "by the formula a structure (dof ≤ 0), overconstrained by 9"
    ));
    assert!(has_note(&m, LOWER));
}

#[test]
fn example_2_5_delta_robot_as_ruu_legs() {
    let m = mech("spatial", Some(8), &[(3, "R"), (6, "U")], None);
    check(&m, 8, 9, 15, 3, "dof = 6(8 − 1 − 9) + 3·1 + 6·2 = 3");
    let m = mech("spatial", None, &[], Some((3, "RUU")));
    check(&m, 8, 9, 15, 3, "dof = 6(8 − 1 − 9) + 3·1 + 6·2 = 3");
    assert_eq!(m.joints_text(), "3R 6U");
}

// ---------- Example 2.6 ----------

#[test]
fn example_2_6_stewart_gough_both_readings() {
    let f = "dof = 6(14 − 1 − 18) + 6·1 + 6·2 + 6·3 = 6";
    let a = mech("spatial", Some(14), &[(6, "U"), (6, "P"), (6, "S")], None);
    check(&a, 14, 18, 36, 6, f);
    let b = mech("spatial", None, &[], Some((6, "UPS")));
    check(&b, 14, 18, 36, 6, f);
    assert_eq!(b.joints_text(), "6U 6P 6S");
    assert!(has_note(&b, LOWER));
    assert!(!has_note(&b, "idle spin"));
    // links given and consistent with the legs: accepted.
    let c = mech("spatial", Some(14), &[], Some((6, "UPS")));
    check(&c, 14, 18, 36, 6, f);
}

#[test]
fn example_2_6_sps_variant_has_twelve() {
    let m = mech("spatial", None, &[], Some((6, "SPS")));
    check(&m, 14, 18, 42, 12, "dof = 6(14 − 1 − 18) + 6·1 + 12·3 = 12");
    assert!(has_note(&m, "6 of the dof are such idle spins"));
}

// ---------- §2.3.1 topologies ----------

#[test]
fn section_2_3_1_topologies() {
    let t =
        |space: &str, n: i64, joints: &[(i64, &str)]| mech(space, Some(n), joints, None).topology();
    assert_eq!(
        t("planar", 3, &[(1, "P"), (1, "R")]).as_deref(),
        Some("R^1 × S^1")
    );
    assert_eq!(t("planar", 3, &[(2, "R")]).as_deref(), Some("T^2"));
    assert_eq!(
        t("spatial", 5, &[(3, "R"), (1, "P")]).as_deref(),
        Some("T^3 × R^1")
    );
    assert_eq!(
        t("spatial", 5, &[(1, "R"), (1, "R"), (1, "R"), (1, "P")]).as_deref(),
        Some("T^3 × R^1")
    );
    assert_eq!(
        t("spatial", 4, &[(1, "R"), (1, "P"), (1, "R")]).as_deref(),
        Some("T^2 × R^1")
    );
    assert_eq!(
        t("spatial", 4, &[(1, "C"), (1, "U"), (1, "H")]).as_deref(),
        Some("T^3 × R^2")
    );
    assert_eq!(
        t("spatial", 3, &[(1, "S"), (1, "P")]).as_deref(),
        Some("SO(3) × R^1")
    );
    assert_eq!(t("spatial", 3, &[(2, "S")]).as_deref(), Some("SO(3)^2"));
    // Free rigid bodies (§2.1, §2.3.1).
    let free = mech("planar", Some(2), &[], None);
    check(&free, 2, 0, 0, 3, "dof = 3(2 − 1 − 0) + 0 = 3");
    assert_eq!(free.topology().as_deref(), Some("R^2 × S^1"));
    assert!(has_note(&free, "a single free planar rigid body"));
    let free = mech("spatial", Some(2), &[], None);
    check(&free, 2, 0, 0, 6, "dof = 6(2 − 1 − 0) + 0 = 6");
    assert_eq!(free.topology().as_deref(), Some("R^3 × SO(3)"));
    assert!(has_note(&free, "writes it S^2 × S^1"));
    // A spherical joint between ground and a body: the same rotations.
    let s = mech("spatial", Some(2), &[(1, "S")], None);
    assert_eq!(s.topology().as_deref(), Some("SO(3)"));
    assert_eq!(
        mech("spherical", Some(2), &[], None).topology().as_deref(),
        Some("SO(3)")
    );
}

#[test]
fn one_leg_is_an_open_chain() {
    let m = mech("spatial", None, &[], Some((1, "RRRP")));
    check(&m, 5, 4, 4, 4, "dof = 6(5 − 1 − 4) + 4·1 = 4");
    assert_eq!(m.topology().as_deref(), Some("T^3 × R^1"));
    assert!(!m.is_closed_chain());
}

// ---------- Exercises, §2.7 ----------

#[test]
fn exercise_5_mobile_manipulators_opening_a_door() {
    // (b) base parked (ground), 6R arm rigidly grasping the door handle, the
    // door hinged to ground: N = 7 (ground, five arm links, hand = door).
    let m = mech("spatial", Some(7), &[(7, "R")], None);
    check(&m, 7, 7, 7, 1, "dof = 6(7 − 1 − 7) + 7·1 = 1");
    // (c) a second identical arm grasps the same handle.
    let m = mech("spatial", Some(12), &[(13, "R")], None);
    check(&m, 12, 13, 13, 1, "dof = 6(12 − 1 − 13) + 13·1 = 1");
}

#[test]
fn exercise_6_srs_arms_grasping_an_object() {
    // (a) three SRS arms.
    let m = mech("spatial", None, &[], Some((3, "SRS")));
    check(&m, 8, 9, 21, 9, "dof = 6(8 − 1 − 9) + 3·1 + 6·3 = 9");
    assert!(has_note(&m, "3 of the dof are such idle spins"));
    // (b) n arms: dof = n + 6.
    for n in 1..=10 {
        let m = mech("spatial", None, &[], Some((n, "SRS")));
        assert_eq!(m.dof(), n + 6);
        assert_eq!(m.links(), 2 + 2 * n);
        assert_eq!(m.joint_count(), 3 * n);
    }
    // (c) the S wrist replaced by a U joint: dof = 6 for any n.
    let m = mech("spatial", None, &[], Some((3, "SRU")));
    check(&m, 8, 9, 18, 6, "dof = 6(8 − 1 − 9) + 3·1 + 3·2 + 3·3 = 6");
    for n in 1..=10 {
        assert_eq!(mech("spatial", None, &[], Some((n, "SRU"))).dof(), 6);
    }
}

#[test]
fn exercise_10_six_ss_platform() {
    let m = mech("spatial", None, &[], Some((6, "SS")));
    check(&m, 8, 12, 36, 6, "dof = 6(8 − 1 − 12) + 12·3 = 6");
    assert!(has_note(&m, "6 of the dof are such idle spins"));
}

#[test]
fn exercise_11_three_upu() {
    let m = mech("spatial", None, &[], Some((3, "UPU")));
    check(&m, 8, 9, 15, 3, "dof = 6(8 − 1 − 9) + 3·1 + 6·2 = 3");
    assert_eq!(m.joints_text(), "6U 3P");
}

#[test]
fn exercise_12a_six_squares_in_a_loop() {
    let m = mech("spatial", Some(6), &[(6, "R")], None);
    check(&m, 6, 6, 6, 0, "dof = 6(6 − 1 − 6) + 6·1 = 0");
    assert!(has_note(&m, "by the formula a structure"));
}

#[test]
fn exercise_13_spherical_four_bar() {
    let m = mech("spherical", Some(4), &[(4, "R")], None);
    check(&m, 4, 4, 4, 1, "dof = 3(4 − 1 − 4) + 4·1 = 1");
    assert_eq!(m.m(), 3);
}

#[test]
fn exercise_14_surgical_manipulator() {
    // (a) legs RRRP, RRRUR, RRRUR: N = 2 + 3 + 4 + 4, J = 4 + 5 + 5.
    let m = mech("spatial", Some(13), &[(11, "R"), (1, "P"), (2, "U")], None);
    check(&m, 13, 14, 16, 4, "dof = 6(13 − 1 − 14) + 12·1 + 2·2 = 4");
    // (c) three RRRR legs, every axis through point A: spherical.
    let m = mech("spherical", None, &[], Some((3, "RRRR")));
    check(&m, 11, 12, 12, 6, "dof = 3(11 − 1 − 12) + 12·1 = 6");
}

#[test]
fn exercise_15_three_pup() {
    let m = mech("spatial", None, &[], Some((3, "PUP")));
    check(&m, 8, 9, 12, 0, "dof = 6(8 − 1 − 9) + 6·1 + 3·2 = 0");
    assert!(has_note(&m, "by the formula a structure"));
    assert!(has_note(&m, LOWER));
}

#[test]
fn exercise_18a_caterpillar() {
    let m = mech("planar", Some(8), &[(7, "RP")], None);
    check(&m, 8, 7, 14, 14, "dof = 3(8 − 1 − 7) + 7·2 = 14");
    assert_eq!(m.topology().as_deref(), Some("T^7 × R^7"));
    assert_eq!(m.joints_text(), "7RP");
    let m = mech("spatial", Some(8), &[(7, "RP")], None);
    check(&m, 8, 7, 14, 14, "dof = 6(8 − 1 − 7) + 7·2 = 14");
}

#[test]
fn exercise_19c_hand_grasping_an_object() {
    // Palm fixed; four URR fingers; each no-slip fingertip contact an S joint.
    let m = mech("spatial", None, &[], Some((4, "URRS")));
    check(
        &m,
        14,
        16,
        28,
        10,
        "dof = 6(14 − 1 − 16) + 8·1 + 4·2 + 4·3 = 10",
    );
}

#[test]
fn exercise_24a_2r_chain_topology() {
    let m = mech("planar", Some(3), &[(2, "R")], None);
    check(&m, 3, 2, 2, 2, "dof = 3(3 − 1 − 2) + 2·1 = 2");
    assert_eq!(m.topology().as_deref(), Some("T^2"));
}

// ---------- Display and JSON ----------

#[test]
fn display_four_bar() {
    let m = mech("planar", Some(4), &[(4, "R")], None);
    let text = m.to_string();
    assert_eq!(
        text,
        "planar mechanism, m = 3\n  N = 4 links (ground included)\n  J = 4 joints: 4R\n  Σf = 4\n  dof = 3(4 − 1 − 4) + 4·1 = 1 (lower bound)\n  note: closed chain, so this is a lower bound: constraints may be dependent (Grübler counts independent constraints; examples 2.4 and 2.5 show it undercounting)"
    );
}

#[test]
fn display_open_chain_and_legs() {
    let m = mech("spatial", Some(5), &[(3, "R"), (1, "P")], None);
    let text = m.to_string();
    assert!(text.contains("  C-space: T^3 × R^1"), "{text}");
    assert!(!text.contains("lower bound"), "{text}");
    let m = mech("spatial", None, &[], Some((6, "UPS")));
    let text = m.to_string();
    assert!(
        text.contains("  J = 18 joints: 6 legs UPS (6U 6P 6S)"),
        "{text}"
    );
}

#[test]
fn json_object() {
    let m = mech("planar", Some(4), &[(4, "R")], None);
    let v = m.to_json();
    assert_eq!(v["dof"], 1);
    assert_eq!(v["m"], 3);
    assert_eq!(v["links"], 4);
    assert_eq!(v["joints"], 4);
    assert_eq!(v["space"], "planar");
    assert_eq!(v["formula"], "dof = 3(4 − 1 − 4) + 4·1 = 1");
    assert!(v["topology"].is_null());
    assert_eq!(v["lower_bound"], true);
    assert!(v["legs"].is_null());
    let v = mech("spatial", None, &[], Some((6, "UPS"))).to_json();
    assert_eq!(v["legs"]["chain"], "UPS");
    assert_eq!(v["legs"]["count"], 6);
}

// ---------- Errors ----------

#[test]
fn error_missing_and_unknown_space() {
    let e = err(None, Some(4), &[(4, "R")], None);
    assert_eq!(e.part, MechPart::Space);
    assert_eq!(
        e.message,
        "the mechanism's space is missing: say planar, spatial or spherical"
    );
    let e = err(Some("flat"), Some(4), &[(4, "R")], None);
    assert_eq!(e.part, MechPart::Space);
    assert_eq!(
        e.message,
        "unknown space `flat`: say planar, spatial or spherical"
    );
}

#[test]
fn error_links() {
    for n in [0, -3] {
        let e = err(Some("planar"), Some(n), &[(4, "R")], None);
        assert_eq!(e.part, MechPart::Links);
        assert_eq!(
            e.message,
            format!("links {n}: a mechanism has at least one link (the ground)")
        );
    }
    let e = err(Some("planar"), Some(1_000_001), &[(4, "R")], None);
    assert_eq!(
        e.message,
        "links 1000001 is absurdly large (at most 1000000)"
    );
    let e = err(Some("planar"), None, &[(4, "R")], None);
    assert_eq!(e.part, MechPart::Links);
    assert_eq!(e.message, "the number of links is missing: write `links N`");
}

#[test]
fn error_no_joints() {
    let e = err(Some("planar"), None, &[], None);
    assert_eq!(e.part, MechPart::Whole);
    assert_eq!(e.message, "no links and no joints: nothing to count");
    let e = err(Some("planar"), Some(4), &[], None);
    assert_eq!(e.part, MechPart::Whole);
    assert_eq!(e.message, "no joints: links 4 with nothing connecting them");
    let e = err(Some("planar"), Some(1), &[], None);
    assert_eq!(e.message, "no joints: links 1 with nothing connecting them");
}

#[test]
fn error_unknown_letter_lists_known_ones() {
    let e = err(Some("spatial"), Some(4), &[(3, "R"), (1, "X")], None);
    assert_eq!(e.part, MechPart::Joint(1));
    assert_eq!(
        e.message,
        "unknown joint letter `X` in `X`: the joints of Table 2.1 are R P H C U S"
    );
    assert!(e.help.as_deref().unwrap().contains("H screw (helical)"));
    let e = err(Some("spatial"), Some(4), &[(1, "RQ")], None);
    assert_eq!(
        e.message,
        "unknown joint letter `Q` in `RQ`: the joints of Table 2.1 are R P H C U S"
    );
    let e = err(Some("spatial"), None, &[], Some((3, "UP7")));
    assert_eq!(e.part, MechPart::Legs);
    assert_eq!(
        e.message,
        "unknown joint letter `7` in `UP7`: the joints of Table 2.1 are R P H C U S"
    );
    let e = err(Some("spatial"), Some(4), &[(1, "")], None);
    assert_eq!(e.message, "a joint has no joint letters");
}

#[test]
fn error_joint_not_in_planar_table_2_1() {
    let e = err(Some("planar"), Some(4), &[(3, "R"), (1, "S")], None);
    assert_eq!(e.part, MechPart::Joint(1));
    assert_eq!(
        e.message,
        "a spherical joint (S) does not exist in a planar mechanism: Table 2.1 lists only R and P between planar rigid bodies (S: N/A)"
    );
    for l in ["H", "C", "U"] {
        let e = err(Some("planar"), Some(4), &[(4, l)], None);
        assert!(
            e.message.contains("does not exist in a planar mechanism"),
            "{}",
            e.message
        );
    }
    let e = err(Some("planar"), None, &[], Some((3, "RPU")));
    assert_eq!(e.part, MechPart::Legs);
    assert!(
        e.message
            .starts_with("a universal joint (U) does not exist in a planar mechanism")
    );
}

#[test]
fn error_spherical_only_revolute() {
    let e = err(Some("spherical"), Some(4), &[(3, "R"), (1, "P")], None);
    assert_eq!(e.part, MechPart::Joint(1));
    assert_eq!(
        e.message,
        "a prismatic joint (P) does not belong in a spherical mechanism: every link only rotates about the common point, so its joints are revolute (R) with axes through that point"
    );
}

#[test]
fn error_counts() {
    let e = err(Some("planar"), Some(4), &[(0, "R")], None);
    assert_eq!(e.part, MechPart::Joint(0));
    assert_eq!(
        e.message,
        "joint count 0 in `0R`: a count must be at least 1"
    );
    let e = err(Some("planar"), Some(4), &[(1, "R"), (-2, "P")], None);
    assert_eq!(e.part, MechPart::Joint(1));
    assert_eq!(
        e.message,
        "joint count -2 in `-2P`: a count must be at least 1"
    );
    let e = err(Some("planar"), Some(4), &[(2_000_000, "R")], None);
    assert_eq!(
        e.message,
        "joint count 2000000 is absurdly large (at most 1000000)"
    );
    let e = err(Some("planar"), Some(4), &[(i64::MAX, "R")], None);
    assert_eq!(e.part, MechPart::Joint(0));
    let e = err(Some("spatial"), None, &[], Some((0, "UPS")));
    assert_eq!(
        e.message,
        "legs 0: a parallel mechanism has at least one leg"
    );
    let e = err(Some("spatial"), None, &[], Some((i64::MIN, "UPS")));
    assert_eq!(e.part, MechPart::Legs);
    let e = err(Some("spatial"), None, &[], Some((10_000_000, "UPS")));
    assert_eq!(
        e.message,
        "legs 10000000 is absurdly large (at most 1000000)"
    );
}

#[test]
fn error_compound_joint_beyond_m() {
    let e = err(Some("planar"), Some(3), &[(1, "RPR"), (1, "RPRP")], None);
    assert_eq!(e.part, MechPart::Joint(1));
    assert_eq!(
        e.message,
        "the compound joint RPRP would provide f = 4 freedoms, more than a planar rigid body has (m = 3)"
    );
}

#[test]
fn error_links_and_legs() {
    let e = err(Some("spatial"), Some(13), &[], Some((6, "UPS")));
    assert_eq!(e.part, MechPart::Links);
    assert_eq!(
        e.message,
        "links 13 disagrees with legs 6 UPS: that parallel mechanism has N = 2 + 6·(3 − 1) = 14 links (fixed and moving platform, 2 per leg)"
    );
    let e = err(Some("spatial"), None, &[(6, "U")], Some((6, "UPS")));
    assert_eq!(e.part, MechPart::Legs);
    assert_eq!(
        e.message,
        "both `joints` and `legs` given: the legs already are the joints"
    );
    let e = err(Some("spatial"), None, &[], Some((6, "")));
    assert_eq!(e.message, "the leg chain has no joint letters");
}

#[test]
fn huge_but_allowed_sizes_do_not_overflow() {
    let big = MAX_COUNT;
    let groups: Vec<(i64, &str)> = vec![(big, "SSSSSS"); 64];
    // f = 18 > m = 6 for a compound SSSSSS: an error, not a panic.
    assert!(Mechanism::from_spec(Some("spatial"), Some(big), &groups, None).is_err());
    let groups: Vec<(i64, &str)> = vec![(big, "S"); 1000];
    let m = mech("spatial", Some(big), &groups, None);
    assert_eq!(m.joint_count(), 1_000_000_000);
    assert_eq!(m.dof(), 6 * (big - 1 - 1_000_000_000) + 3_000_000_000);
    let chain = "S".repeat(MAX_LETTERS);
    let m = mech("spatial", None, &[], Some((big, &chain)));
    assert_eq!(m.links(), 2 + big * (MAX_LETTERS as i64 - 1));
    assert!(m.formula().starts_with("dof = 6("));
    let chain = "S".repeat(MAX_LETTERS + 1);
    let e = err(Some("spatial"), None, &[], Some((1, &chain)));
    assert_eq!(e.message, "the leg chain has more than 1000 joint letters");
}

#[test]
fn lower_case_letters_are_accepted() {
    let m = mech("spatial", None, &[], Some((6, "ups")));
    assert_eq!(m.dof(), 6);
    assert_eq!(m.joints_text(), "6U 6P 6S");
}

#[test]
fn error_compound_joint_leaving_links_apart() {
    // The SCARA of example 2.7, "an RRRP open chain", written as letters:
    // read as one compound joint it would be 6(5 − 1 − 1) + 4 = 22.
    let e = err(Some("spatial"), Some(5), &[(1, "RRRP")], None);
    assert_eq!(e.part, MechPart::Joint(0));
    assert_eq!(
        e.message,
        "`RRRP` is read as one compound joint with f = 4 (as the RP pair of example 2.1), which leaves J = 1 joint for N = 5 links: too few to connect them (J < N − 1 = 4)"
    );
    assert!(e.help.as_deref().is_some_and(|h| h.contains("`R R R P`")));
    let e = err(Some("planar"), Some(9), &[(1, "R"), (2, "RP")], None);
    assert_eq!(e.part, MechPart::Joint(1));
    assert!(
        e.message
            .starts_with("`2RP` is read as 2 compound joints with f = 2 each")
    );
    // Written apart it is the open chain; compound joints that connect
    // every link (the caterpillar, example 2.1(ii)) are as before.
    let m = mech("spatial", Some(5), &[(3, "R"), (1, "P")], None);
    check(&m, 5, 4, 4, 4, "dof = 6(5 − 1 − 4) + 4·1 = 4");
    let m = mech("planar", Some(3), &[(2, "R"), (1, "RP")], None);
    check(&m, 3, 3, 4, 1, "dof = 3(3 − 1 − 3) + 2·1 + 1·2 = 1");
    // Separate joints too few for the links are free bodies, with a note.
    let m = mech("planar", Some(3), &[(1, "R")], None);
    assert!(has_note(&m, "some move as free bodies"));
}

#[test]
fn every_two_s_joints_in_a_row_make_an_idle_spin() {
    // Each SSS leg: the link between S₁ and S₂ spins about their line, and
    // the link between S₂ and S₃ about theirs: two spins a leg.
    let m = mech("spatial", None, &[], Some((3, "SSS")));
    check(&m, 8, 9, 27, 15, "dof = 6(8 − 1 − 9) + 9·3 = 15");
    assert!(has_note(&m, "6 of the dof are such idle spins"), "{m}");
    let m = mech("spatial", None, &[], Some((1, "SRSPS")));
    assert!(has_note(&m, "2 of the dof are such idle spins"), "{m}");
    assert!(m.to_string().contains("J = 5 joints: 1 leg SRSPS"), "{m}");
}
