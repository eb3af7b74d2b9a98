//! From a scene to the figure model: layout, then each layer in turn.

mod acceleration;
mod centres;
mod curves;
mod dimensions;
mod fit;
mod mechanism;
mod scales;
mod torque;
mod velocity;

use super::Layer;
use super::Scene;
use super::cache::{Constructions, Evaluations};
use super::canvas::{Canvas, round};
use super::notation::Named;
use crate::figure::{Figure, PageFromWorld, PageRect, Panel, Role, Shape};
use crate::geom::Point;
use crate::render::NOTE_LINE;
use serde_json::{Map, Value, json};

/// Room kept around the fitted drawing for letters, in page units.
const INSET: f64 = 26.0;
/// Extra room on the slider's side for force arrows.
const FORCE_ROOM: f64 = 80.0;

/// Sizes shared by the layers, in world units.
pub(crate) struct Sizes {
    /// Half the slider block's length along the stroke.
    pub block_half_length: f64,
    /// Half the block's height (the guides are this far from the stroke).
    pub block_half_height: f64,
    /// The slider's nearest and farthest positions.
    pub travel: (f64, f64),
}

impl Sizes {
    fn new(scene: &Scene) -> Self {
        let m = scene.mechanism();
        let (r, l, e) = (m.crank(), m.rod(), m.offset());
        let far = ((l + r - e) * (l + r + e)).sqrt();
        let near = ((l - r - e) * (l - r + e)).sqrt();
        // A short rod brings the slider close to the crank: the block
        // shrinks with l − r (down to 0.3 of its size) so that it does not
        // hide C and B.
        let k = ((l - r) / r).clamp(0.3, 1.0);
        Self {
            block_half_length: 0.36 * r * k,
            block_half_height: 0.2 * r * k,
            travel: (near, far),
        }
    }

    /// Ends of the guides along x.
    pub fn guides(&self, r: f64) -> (f64, f64) {
        (
            self.travel.0 - self.block_half_length - 0.15 * r,
            self.travel.1 + self.block_half_length + 0.15 * r,
        )
    }
}

/// What every layer gets.
pub(crate) struct Ctx<'a> {
    pub scene: &'a Scene,
    pub main: &'a Constructions,
    pub sizes: Sizes,
}

impl Ctx<'_> {
    pub fn letter(&self, n: Named) -> &'static str {
        self.scene.notation().letter(n)
    }

    pub fn line(&self, p: Named, q: Named) -> String {
        self.scene.notation().line(p, q)
    }
}

pub(crate) fn build(scene: &Scene) -> (Figure, Evaluations) {
    let m = scene.mechanism();
    let poses: Vec<Constructions> = scene
        .angles()
        .iter()
        .map(|a| Constructions::new(m.pose(*a)))
        .collect();
    let ctx = Ctx {
        scene,
        main: &poses[0],
        sizes: Sizes::new(scene),
    };

    // Notes first: their number of lines fixes the band below the panel.
    let notes = if scene.has(Layer::Scales) {
        scales::notes(&ctx)
    } else {
        Vec::new()
    };
    let page = scene.page();
    let band = if notes.is_empty() {
        0.0
    } else {
        NOTE_LINE * notes.len() as f64 + 14.0
    };
    let mg = page.margin();
    let panel = PageRect::new(
        mg,
        mg,
        page.width() - 2.0 * mg,
        (page.height() - 2.0 * mg - band).max(20.0),
    );
    let mut inset = [INSET; 4]; // left, right, top, bottom
    if scene.has(Layer::Torque) {
        inset[if scene.is_mirrored() { 0 } else { 1 }] += FORCE_ROOM;
    }
    let mut fit_rect = PageRect::new(
        panel.x + inset[0],
        panel.y + inset[2],
        panel.width - inset[0] - inset[1],
        panel.height - inset[2] - inset[3],
    );
    if fit_rect.width < 20.0 || fit_rect.height < 20.0 {
        fit_rect = panel;
    }
    let world = fit::frame(&ctx);
    let transform = PageFromWorld::fit(&world, &fit_rect, scene.is_mirrored())
        .or_else(|| {
            PageFromWorld::uniform(1.0, scene.is_mirrored(), Point::origin(), panel.centre())
        })
        .expect("a unit map is valid");
    let frame = transform.world_frame(&panel);
    let mut canvas = Canvas::new(transform, frame);

    for layer in scene.layers() {
        match layer {
            Layer::Mechanism => mechanism::draw(&ctx, &poses[1..], &mut canvas),
            Layer::Dimensions => dimensions::draw(&ctx, &mut canvas),
            Layer::Centrodes => curves::centrodes(&ctx, &mut canvas),
            Layer::Coupler => curves::coupler(&ctx, &mut canvas),
            Layer::VirtualCentres => centres::draw(&ctx, &mut canvas),
            Layer::Velocity => velocity::draw(&ctx, &mut canvas),
            Layer::Klein => acceleration::klein(&ctx, &mut canvas),
            Layer::Kisch => acceleration::kisch(&ctx, &mut canvas),
            Layer::Torque => torque::draw(&ctx, &mut canvas),
            Layer::Scales => {}
        }
    }
    if !notes.is_empty() {
        canvas.push(
            "note-scales",
            Role::Label,
            Shape::Note {
                corner: Point::new(mg + 4.0, page.height() - mg - band + 4.0),
                lines: notes,
            },
        );
    }

    let mut evaluations = Evaluations::default();
    for p in &poses {
        evaluations.add(&p.evaluations());
    }
    let (items, points) = canvas.finish();
    let metadata = metadata(scene, points, &evaluations);
    let figure = Figure::new(
        scene.name(),
        page.width(),
        page.height(),
        scene.style(),
        scene.tolerance(),
        vec![Panel::new("panel-mechanism", panel, transform, items)],
        metadata,
    )
    .with_font(scene.font());
    (figure, evaluations)
}

fn metadata(scene: &Scene, points: Map<String, Value>, ev: &Evaluations) -> Map<String, Value> {
    let m = scene.mechanism();
    let mut meta = Map::new();
    meta.insert(
        "mechanism".into(),
        json!({"crank": round(m.crank()), "rod": round(m.rod()), "offset": round(m.offset()), "unit": scene.unit()}),
    );
    meta.insert(
        "angle_deg".into(),
        json!(round(scene.angles()[0].degrees())),
    );
    if scene.angles().len() > 1 {
        let all: Vec<f64> = scene.angles().iter().map(|a| round(a.degrees())).collect();
        meta.insert("angles_deg".into(), json!(all));
    }
    meta.insert("omega".into(), json!(round(scene.omega())));
    meta.insert(
        "layers".into(),
        json!(scene.layers().iter().map(|l| l.name()).collect::<Vec<_>>()),
    );
    meta.insert("notation".into(), json!(scene.notation().name()));
    meta.insert("mirrored".into(), json!(scene.is_mirrored()));
    meta.insert("points".into(), Value::Object(points));
    meta.insert(
        "evaluations".into(),
        serde_json::to_value(ev).unwrap_or(Value::Null),
    );
    meta
}
