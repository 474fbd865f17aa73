//! `explain dof(…)`: Grübler's formula (2.4) with its counts.

mod explain_common;
use explain_common::*;

/// Grübler (2.4): the counts and dof as numbers (Example 2.1, the four-bar).
#[test]
fn grubler_steps_have_the_counts() {
    let o = last_outcome("explain dof(mech < links 4; joints R R R R; planar >)");
    let n = |name| shown(&o, name).as_scalar().unwrap();
    assert_eq!(
        (n("m"), n("N"), n("J"), n("f_i"), n("dof")),
        (3.0, 4.0, 4.0, 4.0, 1.0)
    );
    assert_eq!(o.steps().last().unwrap().reference, "2.4");
}
