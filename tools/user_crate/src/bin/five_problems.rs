use stormer::{Driver, Method, Problem, State};
use user_crate::{HenonHeiles, Pendulum, Pendulum2, Pendulum3, Pendulum4};
fn last<P: Problem<Scalar = f64> + 'static>(p: &P, y0: P::State, method: &Method) -> f64 {
    let mut stepper = method.stepper_for(p, &y0, &Default::default()).unwrap();
    let run = Driver::fixed(0.01).run(p, &mut stepper, 0.0, &y0, 10.0).unwrap();
    run.y.last().unwrap().as_slice()[0]
}
fn main() {
    let name = std::env::args().nth(1).unwrap_or_else(|| "kahan_li6".into());
    let m = Method::resolve(&name).unwrap();
    let sum = last(&Pendulum, [0.5, 0.0], &m)
        + last(&Pendulum2, [0.5, 0.0], &m)
        + last(&Pendulum3, [0.5, 0.0], &m)
        + last(&Pendulum4, [0.5, 0.0], &m)
        + last(&HenonHeiles, [0.1, 0.1, 0.0, 0.0], &m);
    println!("{sum} // edit 0");
}
