//! `carry`: the command line over carry-core (a first cut: the default driver impact).
use carry_core::impact::{self, Solver};
use carry_core::units::{to_deg, to_rpm};
use carry_core::{Ball, ClubSpec, Delivery};

fn main() -> std::process::ExitCode {
    let run = || -> carry_core::Result<()> {
        let club = ClubSpec::<f64>::driver().validate()?;
        let ball = Ball::standard();
        let strike = Delivery::square(45.0, &club).strike(&club)?;
        let out = impact::solve(&club, &ball, &strike, Solver::Reduced)?;
        let l = out.launch;
        println!("ball speed      {:8.3} m/s", l.ball_speed_mps);
        println!("launch angle    {:8.3} deg", to_deg(l.launch_angle_rad));
        println!("launch direction{:8.3} deg", to_deg(l.launch_direction_rad));
        println!("backspin        {:8.1} rpm", to_rpm(l.backspin_radps));
        println!("sidespin        {:8.1} rpm", to_rpm(l.sidespin_radps));
        println!("smash factor    {:8.3}", l.smash_factor);
        Ok(())
    };
    match run() {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("carry: {e}");
            std::process::ExitCode::from(2)
        }
    }
}
