//! The scripts the benchmarks run, shared by `language.rs` and `allocs.rs`.

/// Issue 14's script of `n` statements: a screw axis, then blocks of
/// `T_ab = exp([S] 0.1)`, `T_bc = exp([S] 0.2)`, `T_ac = T_ab * T_bc`,
/// `X = log(T_ac)`, `V_a = Ad(T_ab) * (1, 2, 3, 4, 5, 6)`, every result
/// printed.
pub fn screw_script(n: usize) -> String {
    let lines = [
        "T_ab = exp([S] 0.1)",
        "T_bc = exp([S] 0.2)",
        "T_ac = T_ab * T_bc",
        "X = log(T_ac)",
        "V_a = Ad(T_ab) * (1, 2, 3, 4, 5, 6)",
    ];
    let mut s = String::with_capacity(n * 24);
    s.push_str("S = (0, 0, 1, 0, 2, 0)\n");
    for i in 0..n.saturating_sub(1) {
        s.push_str(lines[i % lines.len()]);
        s.push('\n');
    }
    s
}

/// [`screw_script`] with every statement ended by `;`: the same work,
/// nothing printed (LANGUAGE.md §3).
#[allow(dead_code)]
pub fn silent_screw_script(n: usize) -> String {
    screw_script(n).replace('\n', ";\n")
}

/// A script of `n` statements in the book's style (issue 3).
#[allow(dead_code)]
pub fn book_script(n: usize) -> String {
    let lines = [
        "T_sb = RpToTrans(Rotz(30 deg), (1, 2, 0))",
        "p_s = T_sb * (1, 0, 0)",
        "x = 2 * 3 + 1",
        "w = MatrixLog3(Rotz(0.1) * Rotx(0.2))",
        "V_s = Ad(T_sb) * (0, 0, 1, 1, 0, 0)",
    ];
    let mut s = String::with_capacity(n * 40);
    for i in 0..n {
        s.push_str(lines[i % lines.len()]);
        s.push('\n');
    }
    s
}
