//! Why a method is refused on a scene: the error `stormer run` would report, as text.
//! Shared by the tests of the scenes that refuse splittings.

#![allow(dead_code)] // each test binary uses its part

use stormer::{catalog, Method};
use stormer_app::scenes::{Scene, Setup};

/// The error of building the catalog splitting `name` for the scene, as `stormer run`
/// builds it (`Method::stepper_for`); a splitting the scene accepts fails the test.
pub fn splitting_refusal<S: Scene + 'static>(setup: &Setup<S>, name: &str) -> String {
    let method = Method::Splitting(catalog::find_splitting(name).unwrap());
    match method.stepper_for(&setup.model, &setup.y0, &Default::default()) {
        Ok(_) => panic!("{name} is accepted on {}", setup.name),
        Err(e) => e.to_string(),
    }
}
