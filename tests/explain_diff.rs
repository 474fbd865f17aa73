//! `explain diff(…)`: the chain, power and sum rules step by step.

use chasles::eval::env::Mode;
use chasles::session::{Session, Settings};

/// `diff`: a step per node, bottom up, ending with the derivative itself.
#[test]
fn diff_steps_end_with_the_derivative() {
    let src = "given q(t) : scalar\nx = diff(sin(q)^2 + 3 q, t)\nexplain diff(sin(q)^2 + 3 q, t)";
    let mut session = Session::new(Settings::default());
    let mut outs = Vec::new();
    assert_eq!(
        session.run(src, Mode::Run, false, |r| outs.push(r.result.clone())),
        0
    );
    let explained = outs.pop().unwrap().unwrap();
    let plain = outs.pop().unwrap().unwrap();
    let texts: Vec<&str> = explained.steps().iter().map(|s| s.text.as_str()).collect();
    assert_eq!(explained.steps().len(), 7, "{texts:?}");
    assert!(texts[1].contains("chain rule"), "{texts:?}");
    assert!(texts[2].contains("power rule"), "{texts:?}");
    assert!(texts[6].contains("sum rule"), "{texts:?}");
    assert_eq!(&explained.steps()[6].value, plain.val.as_deref().unwrap());
}
