//! The command that makes a page again, printed in its footer: the
//! program's command line, so that a reader makes the same page from the
//! shell. It is the one text of the library written as the command
//! line's options (a page, not a message, and the same from every front
//! end).

use super::Handout;
use crate::number::plain;

/// The command that makes the handout's page `h` again.
pub(super) fn page_command(h: &Handout) -> String {
    command(h, &dynamics_flags(h))
}

/// The command that makes the exercise sheet of `h` (and its key) again.
pub(super) fn exercise_command(h: &Handout) -> String {
    command(h, &format!("{} --exercise", dynamics_flags(h)))
}

/// The command that makes a class of `sheets` sheets from `seed` again.
pub(super) fn class_command(sheets: usize, seed: u64) -> String {
    format!("slider-crank handout --exercise --class {sheets} --seed {seed}")
}

/// The command that makes this page again.
fn command(h: &Handout, extra: &str) -> String {
    let m = h.mechanism();
    let mut c = format!(
        "slider-crank handout --crank {} --rod {} --offset {} {} --angle {} --unit {} --force-unit {}",
        plain(m.crank()),
        plain(m.rod()),
        plain(m.offset()),
        speed_flag(h.omega()),
        plain(h.angle().degrees()),
        h.units().length().as_str(),
        h.units().force().as_str()
    );
    if let Some(t) = h.torque() {
        c.push_str(&format!(
            " --torque {} --friction {}",
            plain(t),
            plain(h.friction())
        ));
    }
    c.push_str(&format!(" --paper {}", h.paper().name()));
    c.push_str(extra);
    c
}

/// The flags of the dynamics the handout or exercise works, with its gas
/// force (none for the example's), or none.
fn dynamics_flags(h: &Handout) -> String {
    let Some((mass, fluctuation)) = h.dynamics() else {
        return String::new();
    };
    let gas = match h.gas() {
        Some(super::Gas::Constant(f)) => format!(" --gas-force {}", plain(*f)),
        Some(super::Gas::Indicator { bore, source, .. }) => {
            format!(" --indicator {source} --bore {}", plain(*bore))
        }
        _ => String::new(),
    };
    format!(
        " --mass {} --fluctuation {}{gas}",
        plain(mass),
        plain(fluctuation)
    )
}

/// The crank speed as the command line would be given it: `--rpm N` with
/// the shortest N (at most 12 decimals) that gives this very ω back
/// (`--rpm 1500`, not the digits of 50π), else `--omega ω`.
fn speed_flag(omega: f64) -> String {
    let rpm = omega * 60.0 / std::f64::consts::TAU;
    (0..=12)
        .map(|digits| format!("{rpm:.digits$}"))
        .find(|text| text.parse().map(crate::analytic::kinematics::rpm_to_omega) == Ok(omega))
        .map(|text| format!("--rpm {}", plain(text.parse().unwrap_or(rpm))))
        .unwrap_or_else(|| format!("--omega {}", plain(omega)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ω a speed flag gives.
    fn given(flag: &str) -> f64 {
        let (name, value) = flag.split_once(' ').unwrap();
        let value: f64 = value.parse().unwrap();
        match name {
            "--rpm" => crate::analytic::kinematics::rpm_to_omega(value),
            _ => value,
        }
    }

    #[test]
    fn the_command_gives_the_speed_as_it_was_given() {
        assert_eq!(
            speed_flag(crate::analytic::kinematics::rpm_to_omega(1500.0)),
            "--rpm 1500"
        );
        assert_eq!(
            speed_flag(crate::analytic::kinematics::rpm_to_omega(33.25)),
            "--rpm 33.25"
        );
        for omega in [10.0, 157.07963267948966, 1e-3, 0.1 + 0.2] {
            assert_eq!(given(&speed_flag(omega)), omega, "{omega}");
        }
    }
}
