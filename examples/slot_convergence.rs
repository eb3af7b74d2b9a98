//! The curved slot's difference from the straight slot against its radius
//! ρ, from 1 to 1e15: the rows of the log–log convergence figure (textbook
//! Fig. 60 (b) → (c)). Worst over the turn, scaled by r.
//!
//! `cargo run --release --example slot_convergence`

use slider_crank::{SliderCrank, slot_convergence};

fn main() -> Result<(), slider_crank::Error> {
    // r = 0.2, l = 0.6: every ρ ≥ 1 lets the crank turn fully.
    let m = SliderCrank::in_line(0.2, 0.6)?;
    let radii: Vec<f64> = (0..=15).map(|k| 10f64.powi(k)).collect();
    println!("rho,position,velocity,acceleration");
    for row in slot_convergence(&m, &radii, 3600)? {
        println!(
            "{:e},{:e},{:e},{:e}",
            row.radius, row.position, row.velocity, row.acceleration
        );
    }
    Ok(())
}
