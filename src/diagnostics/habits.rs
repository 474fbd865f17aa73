//! Answers for MATLAB and Python habits (LANGUAGE.md §8): what a student
//! types from habit — `syms x`, `format long`, `np.array(...)`, `sind(30)`,
//! `quit` in a script, `RotToQuat(R)` — gets a help line naming the chasles
//! way, never an edit-distance guess that points the wrong way (`RotQuat`
//! is the inverse map of what `RotToQuat` asks for).
//!
//! Pure text in, text out: the evaluator asks [`function`] and [`name`]
//! about unknown functions and names, the session asks [`statement`] about
//! a statement that failed to parse.

/// Help for an unknown function `name` called with arguments `args` (their
/// source text, without the parentheses), or None.
pub fn function(name: &str, args: &str) -> Option<String> {
    let args = args.trim();
    let lower = name.to_lowercase();
    let degrees =
        |f: &str| format!("chasles works in radians: write {f}({args} deg) (or {f}({args}°))");
    Some(match lower.as_str() {
        "sind" | "cosd" | "tand" => degrees(&lower[..3]),
        "asind" | "acosd" | "atand" => format!(
            "for degrees write rad2deg({}({args})): chasles angles are radians",
            &lower[..4]
        ),
        "atan2d" => format!("for degrees write rad2deg(atan2({args}))"),
        "disp" | "print" | "display" | "println" => {
            format!("write the expression on its own line and it prints: {args}")
        }
        "array" | "matrix" | "mat" | "asarray" => format!(
            "write matrices directly: [1, 2; 3, 4] (rows split by `;`), vectors as (1, 2, 3){}",
            if args.starts_with('[') {
                format!(" — here: {}", args)
            } else {
                String::new()
            }
        ),
        "syms" | "sym" | "symbols" | "symbol" => {
            "declare symbols with given: given x, y : scalar".into()
        }
        "quit" | "exit" => {
            "a script ends at its last line; in the REPL type quit, :quit or Ctrl-D".into()
        }
        "help" => "in the REPL type help or :help NAME; on the command line chasles --help".into(),
        "format" => format_help(),
        "matmul" | "mtimes" => format!("multiply with *: {}", args.replace(',', " *")),
        "pinv" => {
            format!("did you mean inv({args})? (square matrices; there is no pseudo-inverse)")
        }
        "transp" | "ctranspose" => format!("did you mean transpose({args}) or ({args}).T?"),
        "deg" => format!("degrees are a unit after the number: {args} deg"),
        _ => return conversion(name),
    })
}

/// Help for an unknown name (not called), or None.
pub fn name(name: &str) -> Option<String> {
    Some(match name {
        "quit" | "exit" => {
            "a script ends at its last line; in the REPL type quit, :quit or Ctrl-D".into()
        }
        // (q is also the book's point on a screw axis, ScrewToAxis(q, s, h))
        "q" => "give q a value first (q = (3, 0, 0), a point on a screw axis) or declare it: given q : vec3; to leave the REPL type quit or :quit".into(),
        "help" => "in the REPL type help or :help NAME; on the command line chasles --help".into(),
        "True" | "TRUE" => "booleans are lower case: true".into(),
        "False" | "FALSE" => "booleans are lower case: false".into(),
        "clc" | "clear" | "clf" => "in the REPL :reset forgets every binding".into(),
        "who" | "whos" => "in the REPL :vars lists the bindings".into(),
        "syms" => "declare symbols with given: given x, y : scalar".into(),
        // (Python's boolean words: a tuple of tests shows each)
        "and" | "or" | "not" => format!(
            "chasles has no `{name}`: test each condition on its own, or show them together as a tuple: (a == 1, a < 2)"
        ),
        "format" => format_help(),
        "rad" | "radians" => "angles are in radians already: pi/6 rad = pi/6".into(),
        "degrees" => "degrees are a unit after the number: 30 deg or 30°".into(),
        // (`Rotz(30 dgr)`: the unit misspelled)
        "dgr" | "dg" | "dge" | "dgs" | "degs" | "degree" | "degr" | "grad" | "grd" => {
            "did you mean `deg`? degrees are a unit after the number: 30 deg or 30°".into()
        }
        _ => return None,
    })
}

/// Help for a statement (its source line) that failed to parse, when it is
/// a MATLAB or Python habit; None otherwise.
pub fn statement(line: &str) -> Option<String> {
    let t = line.trim();
    let first = t.split_whitespace().next().unwrap_or("");
    let rest = t[first.len()..].trim();
    if first == "syms" {
        let names: Vec<&str> = rest.split_whitespace().collect();
        return Some(format!(
            "declare symbols with given: given {} : scalar",
            if names.is_empty() {
                "x".to_string()
            } else {
                names.join(", ")
            }
        ));
    }
    if first == "format" {
        return Some(format_help());
    }
    if first == "import" || (first == "from" && t.contains(" import ")) {
        return Some("nothing to import: every function is built in (:help lists them)".into());
    }
    if matches!(first, "function" | "def") || t.starts_with("lambda") {
        return Some("define a function with an equation: f(x, y) = x^2 + y".into());
    }
    if first.starts_with('%') {
        return Some("comments start with #".into());
    }
    if matches!(t, "clear all" | "close all" | "clear variables") {
        return Some("in the REPL :reset forgets every binding".into());
    }
    if let Some(h) = numpy(t) {
        return Some(h);
    }
    if t.contains(" @ ") || t.contains('@') {
        return Some("multiply matrices with * (or side by side: A B)".into());
    }
    if t.contains(".*") || t.contains(".^") {
        return Some("write * and ^: scalars multiply entrywise already".into());
    }
    None
}

fn format_help() -> String {
    "set the decimals with :digits N in the REPL or --digits N on the command line (up to 17); \
     :exact or --exact prints closed forms such as 1/√2"
        .into()
}

/// `np.array([..])`, `np.sin(x)`, `math.pi`, `np.linalg.inv(A)`: drop the
/// module prefix.
fn numpy(t: &str) -> Option<String> {
    let prefixes = [
        "np.linalg.",
        "numpy.linalg.",
        "np.",
        "numpy.",
        "math.",
        "scipy.linalg.",
    ];
    let p = prefixes.iter().find(|p| {
        t.match_indices(**p).any(|(i, _)| {
            !t[..i]
                .chars()
                .next_back()
                .is_some_and(|c| c.is_alphanumeric() || c == '_')
        })
    })?;
    let at = t.find(p)?;
    let after = &t[at + p.len()..];
    let func: String = after
        .chars()
        .take_while(|c| c.is_alphanumeric() || *c == '_')
        .collect();
    let example = match func.as_str() {
        "array" | "matrix" | "asarray" => {
            "write the array directly: [1, 2, 3] or [[1, 0], [0, 1]]".to_string()
        }
        "pi" => "write pi or π".to_string(),
        "dot" | "matmul" => "dot(a, b) for vectors, * for matrices".to_string(),
        "eye" | "identity" => "eye(3), or I where the size is clear".to_string(),
        "deg2rad" | "radians" => "deg2rad(x), or x deg".to_string(),
        "" => "call the function directly".to_string(),
        f => format!("call {f}(…) directly"),
    };
    Some(format!(
        "chasles needs no `{}` prefix: {example}",
        p.trim_end_matches('.')
    ))
}

/// The kinds of value a conversion name mentions (`Rot`, `quat`, `eul`…).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Repr {
    Rot,
    Quat,
    EulerZyx,
    EulerZxz,
    Rpy,
    AxisAngle,
    Cayley,
    Trans,
    Translation,
}

fn repr(word: &str) -> Option<Repr> {
    use Repr::*;
    Some(match word {
        "rot" | "rotm" | "rotation" | "rotmat" | "r" | "dcm" | "so3" | "matrix" | "mat" => Rot,
        "quat" | "quaternion" | "q" | "quatern" => Quat,
        "eul" | "euler" | "eulerzyx" | "zyx" | "eulzyx" | "eulerangles" => EulerZyx,
        "eulerzxz" | "zxz" | "eulzxz" => EulerZxz,
        "rpy" | "rollpitchyaw" => Rpy,
        "axang" | "axisangle" | "axisang" | "angleaxis" | "axis" | "expc" | "expcoords"
        | "rotvec" => AxisAngle,
        "cayley" | "rodrigues" => Cayley,
        "tform" | "trans" | "transform" | "t" | "se3" | "homogeneous" => Trans,
        "trvec" | "p" | "pos" | "position" | "translation" => Translation,
        _ => return None,
    })
}

/// Help for a name like `RotToQuat`, `rotm2quat`, `quat_to_rot` or
/// `eul2rotm` that asks for a conversion from the first representation to
/// the second: the chasles call that does it (`did you mean quat(R)? …`),
/// or that none does it in one step; None when the name is no conversion.
pub fn conversion(name: &str) -> Option<String> {
    let lower = name.to_lowercase().replace('_', "");
    let splits = lower
        .match_indices("to")
        .map(|(i, _)| (i, 2))
        .chain(lower.match_indices('2').map(|(i, _)| (i, 1)));
    for (i, width) in splits {
        let (from, to) = (&lower[..i], &lower[i + width..]);
        if let (Some(a), Some(b)) = (repr(from), repr(to)) {
            return Some(convert(a, b).map_or_else(
                || {
                    "there is no single function for this conversion; \
                     chain the ones :help representations lists"
                        .to_string()
                },
                |s| format!("did you mean {s}"),
            ));
        }
    }
    None
}

fn convert(from: Repr, to: Repr) -> Option<&'static str> {
    use Repr::*;
    Some(match (from, to) {
        (Rot, Quat) => "quat(R)? It takes a rotation and gives its quaternion (w, x, y, z)",
        (Quat, Rot) => "rot_quat(q)? It takes a quaternion and gives the rotation",
        (Rot, EulerZyx) => "euler_zyx(R)? It takes a rotation and gives its ZYX angles",
        (EulerZyx, Rot) => "rot_zyx(a, b, c)? It takes ZYX angles and gives the rotation",
        (Rot, EulerZxz) => "euler_zxz(R)? It takes a rotation and gives its ZXZ angles",
        (EulerZxz, Rot) => "rot_zxz(a, b, c)? It takes ZXZ angles and gives the rotation",
        (Rot, Rpy) => "rpy(R)? It takes a rotation and gives roll, pitch, yaw",
        (Rpy, Rot) => "rot_rpy(roll, pitch, yaw)? It gives the rotation",
        (Rot, AxisAngle) => {
            "AxisAng3(MatrixLog3(R))? It gives ω̂ and θ of a rotation (log(R) gives [ω̂]θ)"
        }
        (AxisAngle, Rot) => "Rot(w, theta)? It gives the rotation (so does MatrixExp3(w theta))",
        (Rot, Cayley) => "cayley(R)? It takes a rotation and gives its Cayley vector",
        (Cayley, Rot) => "rot_cayley(r)? It takes a Cayley vector and gives the rotation",
        (Quat, EulerZyx) => "euler_zyx(rot_quat(q))?",
        (EulerZyx, Quat) => "quat(rot_zyx(a, b, c))?",
        (Rot, Trans) => "RpToTrans(R, (0, 0, 0))?",
        (Trans, Rot) => "T.R? (or TransToRp(T) for both R and p)",
        (Translation, Trans) => "Trans(p)?",
        (Trans, Translation) => "T.p? (or TransToRp(T) for both R and p)",
        (Trans, AxisAngle) => "MatrixLog6(T)? It gives the exponential coordinates Sθ",
        (AxisAngle, Trans) => "MatrixExp6(S theta)?",
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn conversions_point_the_right_way() {
        for (name, want) in [
            ("RotToQuat", "quat(R)"),
            ("rotm2quat", "quat(R)"),
            ("quat2rotm", "rot_quat(q)"),
            ("QuatToRot", "rot_quat(q)"),
            ("eul2rotm", "rot_zyx("),
            ("rotm2eul", "euler_zyx(R)"),
            ("rot_to_rpy", "rpy(R)"),
            ("tform2rotm", "T.R"),
            ("trvec2tform", "Trans(p)"),
            ("rotm2axang", "AxisAng3(MatrixLog3(R))"),
        ] {
            let got = conversion(name).unwrap_or_default();
            let want = format!("did you mean {want}");
            assert!(got.starts_with(&want), "{name}: {got}");
        }
        assert_eq!(conversion("Rotation"), None);
        // A conversion with no single function never gets an edit-distance guess.
        assert!(
            conversion("rpy2quat")
                .unwrap()
                .contains(":help representations")
        );
        assert_eq!(conversion("total"), None);
    }

    #[test]
    fn matlab_and_python_habits() {
        assert_eq!(
            function("sind", "30").as_deref(),
            Some("chasles works in radians: write sin(30 deg) (or sin(30°))")
        );
        assert!(
            statement("syms t1 t2")
                .unwrap()
                .contains("given t1, t2 : scalar")
        );
        assert!(statement("format long").unwrap().contains(":digits"));
        assert!(statement("np.array([1, 2])").unwrap().contains("[1, 2, 3]"));
        assert!(statement("x = np.sin(0.5)").unwrap().contains("sin(…)"));
        assert!(statement("import numpy as np").is_some());
        assert!(statement("x = snp.sin(1)").is_none());
        assert!(name("quit").unwrap().contains(":quit"));
        // q is the book's point on a screw axis too: never only "quit"
        let q = name("q").unwrap();
        assert!(
            q.contains("given q : vec3") && !q.contains("script ends"),
            "{q}"
        );
        assert_eq!(statement("x = 1 +"), None);
    }
}
