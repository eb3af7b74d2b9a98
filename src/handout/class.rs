//! A class's exercises: different engines drawn from a seed, one sheet and
//! one key each, and a table of every answer for the teacher.
//!
//! The engines are in line, in teaching ranges: n = l/r from 3.5 to 6 in
//! steps of 0.25, a crank radius of round size for the length unit, a
//! crank angle in steps of 5° kept at least 15° from the dead centres and
//! 10° from the quarter turns (where D is at infinity), and a speed from
//! 100 to 1500 rpm in steps of 25. The same seed gives the same engines on
//! every machine and with every build ([`SplitMix64`]).

use super::command::class_command;
use super::page::{footer, style, value_cell};
use super::random::SplitMix64;
use super::steps::{Row, rows, short, show};
use super::{Handout, Paper};
use crate::error::{Error, Field, Result};
use crate::html::{document, rich};
use crate::{angle::Angle, mechanism::SliderCrank};
use maud::html;

/// Most engines in a class.
pub const MAX_CLASS: usize = 999;

/// The crank radii a class draws from, for a length unit: round sizes of
/// an engine's crank in that unit (millimetres for a unit it does not
/// know).
fn radii(unit: &str) -> Vec<f64> {
    let steps = |from: u32, to: u32, step: u32, scale: f64| -> Vec<f64> {
        (from..=to)
            .step_by(step as usize)
            .map(|k| f64::from(k) * scale)
            .collect()
    };
    match unit {
        "ft" => steps(20, 100, 5, 0.01),
        "in" => steps(20, 120, 5, 0.1),
        "cm" => steps(30, 300, 5, 0.1),
        "m" => steps(30, 300, 5, 0.001),
        _ => steps(30, 300, 5, 1.0),
    }
}

/// The crank angles a class draws from, degrees.
fn angles() -> Vec<f64> {
    (0..72)
        .map(|k| f64::from(k) * 5.0)
        .filter(|&d| {
            let from_dead = d.min((d - 180.0).abs()).min(360.0 - d);
            let from_quarter = (d - 90.0).abs().min((d - 270.0).abs());
            from_dead >= 15.0 && from_quarter >= 10.0
        })
        .collect()
}

/// Most engines drawn for a class before it is given up.
const MAX_DRAWS: usize = 200_000;

/// A length as the sheet prints it (four figures: 1148, not 1147.5; 0.95,
/// not 0.9500000000000001), so that the key works from the data on the
/// sheet.
fn printed(x: f64) -> f64 {
    show(x).parse().unwrap_or(x)
}

/// Refuses a class of no students or of more than [`MAX_CLASS`].
fn check_count(count: usize) -> Result<()> {
    if count == 0 || count > MAX_CLASS {
        return Err(Error::OutOfRange {
            name: Field::Class,
            value: count as f64,
            reason: format!("a class has 1 to {MAX_CLASS} students"),
        });
    }
    Ok(())
}

/// A class of exercises.
#[derive(Debug, Clone, PartialEq)]
pub struct Class {
    seed: u64,
    handouts: Vec<Handout>,
}

impl Class {
    /// `count` different engines drawn from `seed`, each set like
    /// `template` (units, torque and friction, paper) but for its engine,
    /// angle and speed, and titled "Exercise k". Errors for a count of 0
    /// or above [`MAX_CLASS`].
    pub fn draw(count: usize, seed: u64, template: &Handout) -> Result<Self> {
        check_count(count)?;
        let radii = radii(template.units().length().as_str());
        let ratios: Vec<f64> = (0..=10).map(|k| 3.5 + 0.25 * f64::from(k)).collect();
        Self::drawn(count, seed, template, |g| {
            let (r, n) = (g.pick(&radii), g.pick(&ratios));
            SliderCrank::in_line(printed(r), printed(r * n)).ok()
        })
    }

    /// `count` different variations of `template`'s own engine drawn from
    /// `seed`, set like it otherwise, as [`Class::draw`]: the crank radius
    /// ×0.8 to ×1.2 in steps of 0.05, the ratio n = l/r ×0.9 to ×1.1 in
    /// steps of 0.05 and the offset in proportion to the crank (e/r kept),
    /// each as the sheet prints it; only variations that assemble
    /// (l > r + |e|), so that every sheet's engine turns fully; the angle
    /// and the speed drawn as for [`Class::draw`].
    ///
    /// Errors: a count of 0 or above [`MAX_CLASS`]; fewer than `count`
    /// different engines found (an engine so near its limit of assembly
    /// that few variations assemble).
    pub fn around(count: usize, seed: u64, template: &Handout) -> Result<Self> {
        check_count(count)?;
        let m = *template.mechanism();
        let steps = |from: i32, to: i32| -> Vec<f64> {
            (from..=to).map(|k| 1.0 + 0.05 * f64::from(k)).collect()
        };
        let (crank, ratio) = (steps(-4, 4), steps(-2, 2));
        Self::drawn(count, seed, template, |g| {
            let (fc, fr) = (g.pick(&crank), g.pick(&ratio));
            let r = printed(m.crank() * fc);
            SliderCrank::new(r, printed(r * m.ratio() * fr), printed(m.offset() * fc)).ok()
        })
    }

    /// `count` different handouts: each engine from `engine` (`None`: one
    /// that does not assemble, drawn again) with an angle and a speed
    /// drawn from `seed`'s generator, until `count` differ or too many
    /// draws have been made.
    fn drawn(
        count: usize,
        seed: u64,
        template: &Handout,
        mut engine: impl FnMut(&mut SplitMix64) -> Option<SliderCrank>,
    ) -> Result<Self> {
        let mut g = SplitMix64::new(seed);
        let angles = angles();
        let speeds: Vec<f64> = (4..=60).map(|k| 25.0 * f64::from(k)).collect();
        let mut drawn: Vec<(SliderCrank, f64, f64)> = Vec::with_capacity(count);
        let mut handouts = Vec::with_capacity(count);
        let mut tries = 0usize;
        while handouts.len() < count {
            tries += 1;
            if tries > MAX_DRAWS {
                return Err(Error::invalid(
                    crate::error::Input::Options,
                    format!(
                        "only {} different engines were found in {MAX_DRAWS} draws for a class of {count}: the engine is too near its limit of assembly (l > r + |e|) for that many variations",
                        handouts.len()
                    ),
                ));
            }
            let Some(mechanism) = engine(&mut g) else {
                continue;
            };
            let (angle, rpm) = (g.pick(&angles), g.pick(&speeds));
            if drawn.contains(&(mechanism, angle, rpm)) {
                continue;
            }
            drawn.push((mechanism, angle, rpm));
            let mut h = template.clone();
            h.mechanism = mechanism;
            h.angle = Angle::from_degrees(angle)?;
            h = h
                .with_omega(crate::analytic::kinematics::rpm_to_omega(rpm))?
                .with_title(format!("Exercise {}", handouts.len() + 1));
            handouts.push(h);
        }
        Ok(Self { seed, handouts })
    }

    /// The seed the class was drawn from.
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// The engines, one per student, in order.
    pub fn handouts(&self) -> &[Handout] {
        &self.handouts
    }

    /// The teacher's table of every answer: one row per exercise, its
    /// data and the values read off the construction.
    pub fn answers(&self) -> Result<String> {
        let paper = self.handouts.first().map_or(Paper::A4, |h| h.paper());
        let mut table: Vec<(usize, &Handout, Vec<Row>)> = Vec::new();
        for (i, h) in self.handouts.iter().enumerate() {
            let reading = h.reading()?;
            let asked = rows(h, &reading).into_iter().filter(|r| r.asked).collect();
            table.push((i + 1, h, asked));
        }
        let header: Vec<Row> = table.first().map(|t| t.2.clone()).unwrap_or_default();
        let units = self.handouts.first().map(|h| h.units().clone());
        let length = units
            .as_ref()
            .map_or("", |u| u.length().as_str())
            .to_string();
        let title = format!("Answers of the class drawn from seed {}", self.seed);
        let body = html! {
            header.title {
                h1 { (title) }
                p.subtitle {
                    (self.handouts.len()) " exercises, in line; lengths in " (length)
                    ". Each value is the one read off the construction where there is one, else the exact one."
                }
            }
            div.block {
                table.values.answers-summary {
                    thead {
                        tr {
                            th { "no." }
                            th { i { "r" } }
                            th { i { "l" } }
                            th { "θ (°)" }
                            th { "rpm" }
                            @for row in &header {
                                th { (rich(&row.quantity)) " (" (rich(&row.unit)) ")" }
                            }
                        }
                    }
                    tbody {
                        @for (no, h, asked) in &table {
                            tr id={ "exercise-" (no) } {
                                td { (no) }
                                td { (short(h.mechanism().crank())) }
                                td { (short(h.mechanism().rod())) }
                                td { (short(h.angle().degrees())) }
                                td { (short(h.rpm())) }
                                @for row in asked {
                                    (value_cell(row.read.as_ref().or(row.exact.as_ref())))
                                }
                            }
                        }
                    }
                }
            }
            (footer(&class_command(self.handouts.len(), self.seed)))
        };
        let style = format!(
            "{}\n@page {{ size: {} landscape; }}\nbody {{ max-width: none; }}\ntable.answers-summary {{ font-size: .8em; }}\ntable.answers-summary th {{ text-align: right; }}\n",
            style(paper),
            paper.css_size()
        );
        Ok(document(&title, &style, body))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn template() -> Handout {
        Handout::new(SliderCrank::in_line(0.5, 3.0).unwrap(), Angle::deg(45.0))
    }

    #[test]
    fn a_seed_gives_the_same_distinct_engines() {
        let a = Class::draw(40, 1, &template()).unwrap();
        let b = Class::draw(40, 1, &template()).unwrap();
        assert_eq!(a, b);
        let c = Class::draw(40, 2, &template()).unwrap();
        assert_ne!(a.handouts(), c.handouts());
        for (i, x) in a.handouts().iter().enumerate() {
            for y in &a.handouts()[i + 1..] {
                assert!(
                    x.mechanism() != y.mechanism()
                        || x.angle() != y.angle()
                        || x.omega() != y.omega()
                );
            }
            let n = x.mechanism().ratio();
            assert!((3.5 - 1e-12..=6.0 + 1e-12).contains(&n), "{n}");
            let d = x.angle().degrees();
            assert!(d % 90.0 >= 10.0 && d % 90.0 <= 80.0 || (d % 180.0 - 90.0).abs() >= 10.0);
        }
    }

    #[test]
    fn a_sheet_prints_the_very_engine_its_key_works() {
        // Issue 22: l = 1147.5 mm was printed 1148, and the key used 1147.5.
        for unit in ["mm", "ft", "in", "m"] {
            let t = template().with_units(crate::units::Units::new(
                unit.parse().unwrap(),
                crate::units::Unit::NEWTON,
            ));
            for h in Class::draw(300, 7, &t).unwrap().handouts() {
                let m = h.mechanism();
                for x in [m.crank(), m.rod()] {
                    assert_eq!(short(x).parse::<f64>(), Ok(x), "{unit}: {x}");
                }
                let rpm: f64 = short(h.rpm()).parse().unwrap();
                assert_eq!(crate::analytic::kinematics::rpm_to_omega(rpm), h.omega());
            }
        }
    }

    #[test]
    fn the_angles_keep_clear_of_dead_centres_and_quarter_turns() {
        for d in angles() {
            for bad in [0.0, 90.0, 180.0, 270.0, 360.0] {
                assert!((d - bad).abs() >= 10.0, "{d}");
            }
        }
    }

    #[test]
    fn a_class_around_an_engine_varies_it_and_every_engine_assembles() {
        let teacher = SliderCrank::new(60.0, 210.0, 12.0).unwrap();
        let t = Handout::new(teacher, Angle::deg(30.0));
        let class = Class::around(200, 3, &t).unwrap();
        let mut cranks = std::collections::BTreeSet::new();
        for h in class.handouts() {
            let m = h.mechanism();
            // Within the variation's bounds, by the formulas: r ×0.8–1.2,
            // n ×0.9–1.1 (to the four printed figures), e/r kept.
            let (fc, fr) = (m.crank() / 60.0, m.ratio() / 3.5);
            assert!((0.8 - 1e-3..=1.2 + 1e-3).contains(&fc), "{fc}");
            assert!((0.9 - 1e-3..=1.1 + 1e-3).contains(&fr), "{fr}");
            assert!(
                (m.offset() / m.crank() - 0.2).abs() < 1e-3,
                "{}",
                m.offset()
            );
            assert!(m.rod() > m.crank() + m.offset().abs());
            assert!(h.reading().is_ok());
            cranks.insert(m.crank().to_bits());
        }
        assert!(cranks.len() >= 5, "the crank varies: {}", cranks.len());
        // Reproducible from its seed.
        assert_eq!(Class::around(200, 3, &t).unwrap(), class);
        // An engine at its limit of assembly: few variations assemble,
        // but those that do are kept, and too many are refused in a line.
        let tight = Handout::new(SliderCrank::new(1.0, 1.06, 0.0).unwrap(), Angle::deg(30.0));
        for h in Class::around(20, 1, &tight).unwrap().handouts() {
            let m = h.mechanism();
            assert!(m.rod() > m.crank() + m.offset().abs());
        }
    }

    #[test]
    fn an_empty_or_huge_class_is_refused() {
        assert!(Class::draw(0, 1, &template()).is_err());
        assert!(Class::draw(MAX_CLASS + 1, 1, &template()).is_err());
    }
}
