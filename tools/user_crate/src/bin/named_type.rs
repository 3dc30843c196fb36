use stormer::catalog::Rk4;
use stormer::Driver;
use stormer::stepper::ExplicitRk;
use user_crate::Pendulum;
fn main() {
    let y0 = [0.5, 0.0];
    let mut stepper = ExplicitRk::<Rk4, [f64; 2]>::new(&y0);
    let run = Driver::fixed(0.01).run(&Pendulum, &mut stepper, 0.0, &y0, 10.0).unwrap();
    println!("{:?} // edit 0", run.y.last());
}
