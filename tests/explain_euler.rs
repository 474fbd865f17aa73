//! `explain` of the Euler angles and roll–pitch–yaw (App. B).

mod common;

/// Near gimbal lock (cos b = 1e-16, not 0: r₁₁ and r₂₁ are typed as
/// nonzero) rpy decides the lock by R's exact entries; explain takes the
/// same branch (App. B), so its yaw, pitch and roll steps are the angles
/// of the value, not those of a lock the value did not take.
#[test]
fn euler_steps_take_the_gimbal_branch_of_the_value() {
    let r = "R = [-9.61014653969206e-17, 0.7654818453520746, -0.6434574923305988; \
             5.559190581948764e-17, -0.6434574923305988, -0.7654818453520746; \
             -1.0, -1.0933495538555965e-16, 1.9282613280258205e-17]";
    for (f, names) in [
        ("rpy", ["roll", "pitch", "yaw"]),
        ("euler_zyx", ["c", "b", "a"]),
    ] {
        let lines = common::json(&format!("{r}\nexplain {f}(R)"));
        let steps = lines[1]["steps"].as_array().unwrap();
        let by = |name: &str| steps.iter().find(|s| s["name"] == name).unwrap();
        assert_eq!(by("case")["value"], "general", "{f}: {steps:?}");
        let value = common::numbers(&lines[1]["value"]);
        let shown: Vec<f64> = names
            .iter()
            .map(|n| by(n)["value"].as_f64().unwrap())
            .collect();
        let shown = if f == "rpy" {
            shown
        } else {
            shown.into_iter().rev().collect()
        };
        assert_eq!(shown, value, "{f}");
    }
}
