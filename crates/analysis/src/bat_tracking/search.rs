//! The one-dimensional searches the swing solve uses.

/// A root of g between a and b (g(a) ≤ 0 ≤ g(b) or the reverse), by the
/// Illinois variant of regula falsi, to `tolerance` in the argument.
pub(super) fn illinois(
    mut g: impl FnMut(f64) -> f64,
    ((mut a, mut ga), (mut b, mut gb)): ((f64, f64), (f64, f64)),
    tolerance: f64,
) -> f64 {
    let mut side = 0;
    for _ in 0..100 {
        if ga == 0.0 {
            return a;
        }
        if gb == 0.0 {
            return b;
        }
        let c = (a * gb - b * ga) / (gb - ga);
        let gc = g(c);
        if gc.is_nan() {
            // Outside where g is defined: bisect instead.
            let m = 0.5 * (a + b);
            let gm = g(m);
            if gm.is_nan() {
                return c;
            }
            if (gm > 0.0) == (gb > 0.0) {
                (b, gb) = (m, gm);
            } else {
                (a, ga) = (m, gm);
            }
            continue;
        }
        if (gc > 0.0) == (gb > 0.0) {
            (b, gb) = (c, gc);
            if side == 1 {
                ga *= 0.5;
            }
            side = 1;
        } else {
            (a, ga) = (c, gc);
            if side == -1 {
                gb *= 0.5;
            }
            side = -1;
        }
        if (b - a).abs() < tolerance || gc == 0.0 {
            return c;
        }
    }
    0.5 * (a + b)
}

/// The most of `f` on [a, b] and where: a golden-section search, 32
/// narrowings (to 2e-7 of the interval: the most is flat there, to 1e-13
/// of itself).
pub(super) fn golden_max(mut f: impl FnMut(f64) -> f64, mut a: f64, mut b: f64) -> (f64, f64) {
    let ratio = (5f64.sqrt() - 1.0) / 2.0;
    let mut c = b - ratio * (b - a);
    let mut d = a + ratio * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..32 {
        if fc > fd {
            (b, d, fd) = (d, c, fc);
            c = b - ratio * (b - a);
            fc = f(c);
        } else {
            (a, c, fc) = (c, d, fd);
            d = a + ratio * (b - a);
            fd = f(d);
        }
    }
    if fc > fd { (c, fc) } else { (d, fd) }
}

/// `end`, or the first point from it toward `inner` (halving the way)
/// where `f` is defined, and f there.
pub(super) fn defined_toward(f: impl Fn(f64) -> f64, end: f64, inner: f64) -> (f64, f64) {
    let mut x = end;
    for _ in 0..30 {
        let value = f(x);
        if !value.is_nan() {
            return (x, value);
        }
        x = 0.5 * (x + inner);
    }
    (inner, f(inner))
}
