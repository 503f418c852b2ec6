use homerun::{Purpose, Scene, simulate};
fn main() {
    for (speed, spin, e, psi) in [
        (42.0, -200.0, 0.0265, 0.1594),
        (36.0, 0.0, 0.0250, 0.1549),
        (35.0, 200.0, 0.0223, 0.1152),
    ] {
        let mut s = Scene::default();
        s.pitch.speed = speed;
        s.pitch.spin = spin;
        s.bat.undercut = e;
        s.bat.swing_angle = psi;
        for p in [
            Purpose::Reference,
            Purpose::Readout,
            Purpose::Optimizer,
            Purpose::Surface,
        ] {
            let w = simulate(&s, p);
            println!(
                "{:?} {:.4} {:.3} {:.5} range {:.6} t {:.6} apex {:.3} {:?}",
                p,
                w.impact.launch_speed(),
                w.impact.launch_spin(),
                w.impact.launch_angle(),
                w.flight.range,
                w.flight.flight_time,
                w.flight.apex,
                w.flight.stats
            );
        }
    }
}
