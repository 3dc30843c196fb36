use stormer::{Driver, Method};
use user_crate::Pendulum;
fn main() {
    let name = std::env::args().nth(1).unwrap_or_else(|| "rk4".into());
    let y0 = [0.5, 0.0];
    let method = Method::resolve(&name).unwrap();
    let mut stepper = method.stepper_for(&Pendulum, &y0, &Default::default()).unwrap();
    let run = Driver::fixed(0.01).run(&Pendulum, &mut stepper, 0.0, &y0, 10.0).unwrap();
    println!("{:?} // edit 0", run.y.last());
}
