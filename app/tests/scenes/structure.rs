//! Symplectic structure on the charged-particle scenes.

/// The structure the `charged-particles` scenes supply (`ChargedParticles` implements
/// `Structure`: per particle `[[m K, m I], [-m I, 0]]`), on the `penning-trap` scene
/// (three ions, uniform B, quadrupole, Coulomb repulsion) and on `coulomb-magnetic`
/// (docs/scenes.md 5), one step at `h = 0.01` and `h = 0.1` from the scene's initial state:
///
/// - the magnetic Verlet and Kahan-Li 6 over it keep it to round-off (measured at most
///   12 eps |J|^2, against a bound of `SYMPLECTIC_FACTOR` = 100);
/// - Boris (both rotations) keeps the phase-space volume (`|det J - 1|` at most 1.3e-15;
///   in the non-uniform field of `magnetic-bottle` too) but not the two-form (defect 7.5e8 to 1.2e14 eps |J|^2); so does Euler-Cromer (each
///   velocity component is updated by a shear), with defects 4.5e11 to 1.1e15;
/// - explicit Euler keeps neither (`det J - 1` from 1e-4 to 0.97).
mod scene_structure {
    use nalgebra::DVector;
    use stormer::magnetic::Charged;
    use stormer::models::ChargedParticles;
    use stormer::real::lit;
    use stormer::stepper::ParticleMethod;
    use stormer::verify::{defect_bound, jacobian_dual, symplectic_defect, Dual64, SYMPLECTIC_FACTOR};
    use stormer::{Method, Stepper};
    use stormer_app::scenes::{self, AnyScene};

    type Model = ChargedParticles<Dual64, DVector<Dual64>>;

    /// `(defect / (eps |J|^2), |det J - 1|)` of one step of `name` from the scene's start.
    fn step_checks(scene: &str, name: &str, h: f64) -> (f64, f64) {
        let AnyScene::ChargedParticles(s) = scenes::load(scene).unwrap() else {
            panic!("{scene}")
        };
        let model: Model = s.model.0.converted();
        let p = Charged(model);
        let y: DVector<Dual64> = s.y0.map(lit);
        let mut stepper: Box<dyn Stepper<Charged<Model>>> = match ParticleMethod::find(name) {
            Some(m) => m.stepper::<Model>(&y).unwrap(),
            None => Method::named(name)
                .unwrap()
                .stepper_for(&p, &y, &Default::default())
                .unwrap(),
        };
        let j = jacobian_dual(&mut stepper, &p, 0.0, h, &y).unwrap();
        let mut y1 = y.clone();
        stepper.reset();
        stepper.step(&p, lit(0.0), lit(h), &y, &mut y1).unwrap();
        let y1: Vec<f64> = y1.iter().map(|x| x.re).collect();
        // the structure matrix the scene's model supplies
        let defect = symplectic_defect(&j, &s.model.0, s.y0.as_slice(), &y1) / defect_bound(&j, 1.0);
        (defect, (j.determinant() - 1.0).abs())
    }

    #[test]
    fn magnetic_verlet_is_symplectic_boris_keeps_volume_only_euler_neither() {
        for scene in ["penning-trap", "coulomb-magnetic"] {
            for h in [0.01, 0.1] {
                for name in ["velocity_verlet_kdk", "kahan_li6"] {
                    let (defect, _) = step_checks(scene, name, h);
                    assert!(
                        defect <= SYMPLECTIC_FACTOR,
                        "{scene}, {name}, h = {h}: {defect} eps |J|^2"
                    );
                }
                for name in ["boris", "boris_exact_phase", "euler_cromer"] {
                    let (defect, volume) = step_checks(scene, name, h);
                    assert!(volume <= 1e-14, "{scene}, {name}, h = {h}: |det J - 1| = {volume:e}");
                    assert!(
                        defect >= 1e6 * SYMPLECTIC_FACTOR,
                        "{scene}, {name}, h = {h}: defect only {defect} eps |J|^2"
                    );
                }
                let (defect, volume) = step_checks(scene, "euler", h);
                assert!(volume >= 1e-5, "{scene}, euler, h = {h}: |det J - 1| = {volume:e}");
                assert!(defect >= 1e6 * SYMPLECTIC_FACTOR, "{scene}, euler, h = {h}: {defect}");
            }
        }
    }

    /// In the non-uniform field of `magnetic-bottle` Boris keeps the volume too: it reads the
    /// field once, at the middle of the step, where the kick (an electric shift and a
    /// rotation at fixed positions) and the drifts (shears) each keep it (issue #30, defect
    /// 9: with the field read at both ends of the step, `det J - 1` was -8e-5 at `h = 0.1`).
    #[test]
    fn boris_keeps_the_volume_in_a_non_uniform_field() {
        for name in ["boris", "boris_exact_phase"] {
            for h in [0.01, 0.1] {
                let (_, volume) = step_checks("magnetic-bottle", name, h);
                assert!(
                    volume <= 1e-14,
                    "magnetic-bottle, {name}, h = {h}: |det J - 1| = {volume:e}"
                );
            }
        }
    }
}
