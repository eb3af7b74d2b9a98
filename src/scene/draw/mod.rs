//! From a scene to the figure model: layout, then each layer in turn.

mod acceleration;
mod centres;
mod curves;
mod detail;
mod dimensions;
mod fit;
mod joint;
mod mechanism;
pub(crate) use mechanism::{LINK_BESIDE, LINK_JOG, path_beside};
mod motion;
pub(crate) mod polygons;
mod scales;
mod torque;
mod velocity;

pub(crate) use joint::letter_near_together;
pub(crate) use polygons::COINCIDE;
pub(crate) use torque::torque_arrow;

use super::Layer;
use super::Scene;
use super::cache::{Constructions, Evaluations};
use super::canvas::{Canvas, round};
use super::notation::Named;
use crate::angle::Angle;
use crate::figure::{
    Align, EngineRecord, Figure, Hue, Metadata, PageFromWorld, Panel, Part, RichText, Role, Shape,
    TextSize,
};
use crate::figure::{
    BEARING_FOOT, Foot, HATCH_DEPTH, LETTER_SIZE, NOTE_LINE, NOTE_SIZE, SMALL_DETAIL_EMS,
};
use crate::geom::{Frame, Point, Vector};
use crate::scene::linkage::HATCH_SLANT;
use serde_json::{Map, Value, json};

/// Room kept around the fitted drawing for letters, in page units.
const INSET: f64 = 26.0;

/// Sizes shared by the layers, in world units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Sizes {
    /// Half the slider block's length along the stroke.
    pub block_half_length: f64,
    /// Half the block's height (the guides are this far from the stroke).
    pub block_half_height: f64,
    /// The most half length the block may have without coming near the
    /// crank centre at the inner dead centre: 0.36 of the slider's nearest
    /// distance from it (at least 0.36 × 0.3 r).
    block_room: f64,
    /// The slider's nearest and farthest positions.
    pub travel: (f64, f64),
    /// The crank's length r.
    crank: f64,
    /// The offset e of the line of stroke.
    offset: f64,
    /// Page units per world unit of the main view, once a first fit has
    /// found it: then arrows drawn to page lengths are fitted too.
    pub page_scale: Option<f64>,
    /// The world frame the main view was fitted to (over every held pose),
    /// once fitted: what the drawing reaches, for what is set beyond it.
    pub fitted: Option<Frame>,
    /// The slider block's ends (world x) on a view of one pose that draws
    /// the mechanism, once fitted: a detail's frame keeps its sides off
    /// them ([`detail_frame`]). None on a view held over several poses,
    /// where the block moves.
    block_ends: Option<(f64, f64)>,
}

/// The slider block on the page, page units: its largest half length,
/// small enough that A's letter, kept out of the block, stays within
/// 1.5 em of A beside it; and its half height, which is also the
/// channel between the line of stroke and a guide, tall enough for a
/// letter to sit there clear of both.
const BLOCK_HALF_LENGTH_MOST: f64 = 20.0;
const BLOCK_HALF_HEIGHT: f64 = 18.0;

impl Sizes {
    /// The sizes in proportion to the crank (the fit's first pass).
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
            block_room: 0.36 * near.max(0.3 * r),
            travel: (near, far),
            crank: r,
            offset: e,
            page_scale: None,
            fitted: None,
            block_ends: None,
        }
    }

    /// The block sized on the page at `scale` page units per world unit:
    /// [`BLOCK_HALF_HEIGHT`] high, and [`BLOCK_HALF_LENGTH_MOST`] long
    /// where the slider keeps far enough from the crank centre (shorter
    /// where the rod is short). A small crank on a long rod does not make
    /// the block a thin bar: its length follows the slider's distance from
    /// the crank, not the crank.
    /// The channel between the guides is moved clear of the `turns` of
    /// curves drawn on the mechanism (world x and height above the line
    /// of stroke) that lie over the guides' stretch or within
    /// [`TURN_REACH`] cranks of it ([`channel_clear_of`]).
    fn on_page(self, scale: f64, turns: &[(f64, f64)]) -> Self {
        if !(scale.is_finite() && scale > 0.0) {
            return self;
        }
        let room = self.block_room.max(self.block_half_length);
        let block_half_length = room.min(BLOCK_HALF_LENGTH_MOST / scale);
        let (x0, x1) = Self {
            block_half_length,
            ..self
        }
        .guides();
        let reach = TURN_REACH * self.crank;
        let turns: Vec<f64> = (turns.iter())
            .filter(|(x, _)| (x0 - reach..=x1 + reach).contains(x))
            .map(|(_, y)| y.abs() * scale)
            .collect();
        Self {
            block_half_length,
            block_half_height: channel_clear_of(&turns) / scale,
            page_scale: Some(scale),
            ..self
        }
    }

    /// Heights of the guides (world y): the line of stroke and the
    /// block's half height either side.
    fn guide_heights(&self) -> [f64; 2] {
        [
            self.offset - self.block_half_height,
            self.offset + self.block_half_height,
        ]
    }

    /// Ends of the guides along x: the block's whole travel and 0.15 r
    /// beyond.
    pub fn guides(&self) -> (f64, f64) {
        let r = self.crank;
        (
            self.travel.0 - self.block_half_length - 0.15 * r,
            self.travel.1 + self.block_half_length + 0.15 * r,
        )
    }
}

/// The least and most half height of the channel between the guides,
/// page units, where it moves clear of a curve's turns.
const CHANNEL: (f64, f64) = (12.0, 27.0);

/// How far beyond the guides' stretch (in cranks) a curve's turn still
/// moves the channel: a flat oval runs along a line on either side of
/// its turn.
const TURN_REACH: f64 = 0.5;

/// How far (page units) a curve's turn keeps from a guide's line and its
/// hatching before the channel moves.
const CLEAR_OF_TURN: f64 = 8.0;

/// The half height (page units) of the channel between the guides: the
/// block's [`BLOCK_HALF_HEIGHT`] where every turn of a curve drawn on the
/// mechanism (`turns`: page distances from the line of stroke) keeps
/// [`CLEAR_OF_TURN`] from the guide on its side, line and hatching;
/// else the height within [`CHANNEL`], in half units, that leaves the
/// nearest turn farthest off (the first of equals). A turn on a guide
/// or its hatching is a curve running along it, which no reader tells
/// from the guide.
fn channel_clear_of(turns: &[f64]) -> f64 {
    let clearance = |h: f64| {
        let off = |t: f64| {
            if t < h {
                h - t
            } else {
                (t - h - HATCH_DEPTH).max(0.0)
            }
        };
        turns.iter().map(|&t| off(t)).fold(f64::INFINITY, f64::min)
    };
    if clearance(BLOCK_HALF_HEIGHT) >= CLEAR_OF_TURN {
        return BLOCK_HALF_HEIGHT;
    }
    let steps = (2.0 * (CHANNEL.1 - CHANNEL.0)) as u32;
    (0..=steps)
        .map(|k| CHANNEL.0 + 0.5 * f64::from(k))
        .fold((BLOCK_HALF_HEIGHT, f64::NEG_INFINITY), |best, h| {
            let c = clearance(h);
            if c > best.1 { (h, c) } else { best }
        })
        .0
}

/// An arrow drawn with its name: its id and name, tail and head, and
/// where its name is set (world units).
pub(crate) struct NamedArrow {
    pub id: &'static str,
    pub name: &'static str,
    pub from: Point,
    pub to: Point,
    /// Its head, or its tail for an arrow that points at what it acts on
    /// (F_c at the crank pin).
    pub name_at: Point,
}

/// Room for an arrow's name beyond its ends, page units.
const NAME_ROOM: f64 = 26.0;

impl NamedArrow {
    /// The arrow's ends moved outwards by room for its name (`world`
    /// turns page lengths into world lengths): what the page must hold.
    pub(crate) fn reach(&self, world: &dyn Fn(f64) -> f64) -> [Point; 2] {
        let d = self.to - self.from;
        let room = d / d.norm() * world(NAME_ROOM);
        [self.from - room, self.to + room]
    }

    /// Draws the arrow (`{kind}-{id}`, a force's stroke in the colour of
    /// `hue`) and its name (`value-{id}`).
    pub(crate) fn draw(&self, canvas: &mut Canvas, kind: &str, hue: Hue) {
        let arrow = Shape::Arrow {
            from: self.from,
            to: self.to,
        };
        canvas.push_hued(format!("{kind}-{}", self.id), Role::Force, hue, arrow);
        let name = RichText::parse(self.name);
        canvas.label(
            format!("value-{}", self.id),
            self.name_at,
            name,
            TextSize::Small,
        );
    }
}

/// What every layer gets.
pub(crate) struct LayerCtx<'a> {
    pub scene: &'a Scene,
    pub main: &'a Constructions,
    pub sizes: Sizes,
    /// The side the crank centre's bearing stands on as the main view
    /// has it, which a detail keeps (chosen again at the detail's scale,
    /// the wall at C stood on one side of C in the main view and on the
    /// other in the detail); `None` until the main view is drawn.
    pub foot: Option<crate::figure::Foot>,
}

impl LayerCtx<'_> {
    pub fn letter(&self, n: Named) -> &'static str {
        self.scene.notation().letter(n)
    }

    pub fn line(&self, p: Named, q: Named) -> String {
        self.scene.notation().line(p, q)
    }
}

/// Fits of the main view: the first in proportion to the crank, the
/// others with page-sized block and arrows at the scale found before.
const FITS: usize = 4;

/// Room between the main view and the detail below it, page units.
const DETAIL_GAP: f64 = 10.0;
/// Height of the detail's caption line, page units.
const CAPTION: f64 = 22.0;
/// Room between the detail and the notes below it, page units.
const NOTE_GAP: f64 = 8.0;

/// Where a figure's drawing goes on the page: the block's sizes, the room
/// kept for the notes, the main view's panel and map, and the detail.
/// Fitted to one pose ([`fit`]) or held over several ([`held_view`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Layout {
    sizes: Sizes,
    /// The notes' band the fit left room for, page units.
    band: f64,
    main: Frame,
    transform: PageFromWorld,
    detail: Option<detail::Detail>,
    /// The crank centre's bearing as the main view stands it, where the
    /// scene draws the mechanism: a detail's frame keeps off its base.
    bearing: Option<Bearing>,
}

/// The crank centre's bearing on the main view: C, the side it stands
/// on, and the world direction (a unit vector along x or y) from C out
/// to its base.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Bearing {
    c: Point,
    foot: Foot,
    out: Vector,
    /// The page width (page units) a detail may take.
    width: f64,
    /// Whether a detail may grow to take the bearing in: not on a page of
    /// fixed height, where the detail's size is its own and a frame grown
    /// by page units does not shrink with the main view (Fig. 67 on a page
    /// 1000 tall needed 1031).
    grows: bool,
}

impl Bearing {
    /// The bearing of the main view `main` drawn by `transform` at the
    /// pose of `ctx` ([`mechanism::foot`]); none where the scene draws no
    /// mechanism.
    fn of(ctx: &LayerCtx, main: &Frame, transform: PageFromWorld) -> Option<Self> {
        if !ctx.scene.has(Layer::Mechanism) {
            return None;
        }
        let canvas = Canvas::new(transform, transform.world_frame(main));
        let foot = mechanism::foot(ctx, &canvas);
        let out = transform.inverse().apply_vector(foot.axes().0);
        let page = ctx.scene.page();
        Some(Self {
            c: ctx.main.pose().c(),
            foot,
            out: out / out.norm(),
            width: page.width() - 2.0 * page.margin(),
            grows: !page.has_fixed_height(),
        })
    }

    /// The world band its pedestal, base and hatching take, from just
    /// past the pin ([`PEDESTAL_FROM`]) out along `out` (least, most),
    /// and the stretch of the base across it (least, most), drawn at
    /// `scale`: whether the band runs across y (`true`, a bearing
    /// standing below or hanging) or across x (a wall). A frame's edge
    /// through the pedestal cuts the ground symbol in two (Klein's
    /// default, the twenty-ninth review), as one along the base reads as
    /// the base.
    fn base(&self, scale: f64) -> (bool, (f64, f64), (f64, f64)) {
        let (depth, half) = BEARING_FOOT;
        let (near, far) = (PEDESTAL_FROM / scale, (depth + HATCH_DEPTH) / scale);
        let across = (half + HATCH_SLANT) / scale;
        let along_y = self.out.y.abs() > self.out.x.abs();
        let (at, side, sign) = match along_y {
            true => (self.c.y, self.c.x, self.out.y.signum()),
            false => (self.c.x, self.c.y, self.out.x.signum()),
        };
        let (a, b) = (at + sign * near, at + sign * far);
        (
            along_y,
            (a.min(b), a.max(b)),
            (side - across, side + across),
        )
    }
}

/// The notes of the scene at the pose of `ctx`: their number of lines
/// fixes the band below the panels.
fn notes(ctx: &LayerCtx) -> Vec<RichText> {
    let scene = ctx.scene;
    let mut notes = if scene.has(Layer::Scales) {
        scales::notes(ctx)
    } else {
        Vec::new()
    };
    if scene.has(Layer::Torque) {
        notes.extend(torque::notes(ctx));
    }
    if scene.has(Layer::Polygons) {
        notes.extend(polygons::notes(ctx));
    }
    if scene.has(Layer::Bennett) && scene.mechanism().offset() != 0.0 {
        notes.push(RichText::parse(
            "Bennett’s construction is the in-line engine’s: with an offset its fixed length *r*²/*l* no longer gives the acceleration, and it is not drawn.",
        ));
    }
    if scene.mechanism().offset() != 0.0 {
        notes.push(RichText::parse(&offset_note(scene)));
    }
    if scene.has(Layer::Angles) {
        notes.extend(dimensions::phi_note(ctx, "φ"));
    }
    // Each note broken into lines that fit the page at the notes' size
    // (set from `mg + 4` with 8 units to spare, as the writer sets them),
    // so that a narrow page adds lines instead of shrinking the type.
    let page = scene.page();
    let room = page.width() - 2.0 * page.margin() - 12.0;
    notes
        .iter()
        .flat_map(|n| n.wrap(scene.font(), NOTE_SIZE, room))
        .collect()
}

/// The band the notes take below the panels, page units.
fn band(notes: &[RichText]) -> f64 {
    if notes.is_empty() {
        0.0
    } else {
        NOTE_LINE * notes.len() as f64 + 14.0
    }
}

/// The layout fitted to the scene's own (first) pose and its notes.
// cannot fail: a scene is laid out only once `valid::scene` has passed it,
// which refuses one without a pose.
#[allow(clippy::indexing_slicing)]
pub(crate) fn own(scene: &Scene) -> Layout {
    let poses = own_poses(scene);
    let ctx = LayerCtx {
        scene,
        main: &poses[0],
        sizes: Sizes::new(scene),
        foot: None,
    };
    let before = band(&notes(&ctx));
    let layout = fit_within(&ctx, before);
    if !scene.page().has_fixed_height() {
        return layout;
    }
    // The notes read at the page's scale may be one more (a polygon's
    // side too short for an arrow, [`polygons::notes`]): a page free to
    // grow grows for it ([`build`]), a fixed one is fitted again with
    // room for it. At the smaller scale the side is shorter still: once
    // is enough.
    match band(&notes(&LayerCtx {
        sizes: layout.sizes,
        ..ctx
    })) {
        after if after > before => fit_within(&ctx, after),
        _ => layout,
    }
}

/// The width of the page (page units, margins included) that the scene's
/// drawing in `layout` takes: its main view's drawing with the view's
/// insets, or its detail where that is wider.
pub(crate) fn used_width(scene: &Scene, layout: &Layout) -> f64 {
    let scale = layout.transform.scale();
    let mg = scene.page().margin();
    let drawn = layout.sizes.fitted.map_or(layout.main.width(), |world| {
        (world.max().x - world.min().x) * scale + 2.0 * INSET
    });
    let detail = layout.detail.map_or(0.0, |d| {
        let frame = detail_frame(&d, scale, &layout.sizes, layout.bearing.as_ref());
        (frame.max().x - frame.min().x) * scale * d.magnification
    });
    drawn.max(detail) + 2.0 * mg
}

/// The layout fitted to the pose of `ctx` with its notes' `band`; on a
/// page whose height is fixed ([`crate::scene::Page::has_fixed_height`]),
/// fitted again with the main view shrunk by what the figure took past
/// the height (the dimensions stacked below the guides, a detail), until
/// it ends within it or [`HEIGHT_REFITS`] tries are spent (a detail's
/// size is its own, not the main view's: such a figure may still not fit,
/// and is refused by the scene).
fn fit_within(ctx: &LayerCtx, band: f64) -> Layout {
    let page = ctx.scene.page();
    let mut layout = fit(ctx, band);
    let mut reserve = band;
    for _ in 0..HEIGHT_REFITS {
        let over = layout.height(band, page.margin()) - page.height();
        if !page.has_fixed_height() || over <= 0.0 {
            break;
        }
        reserve += over;
        layout = fit(ctx, reserve);
        layout.band = band;
    }
    layout
}

/// The most refits [`fit_within`] makes to end within a fixed height.
const HEIGHT_REFITS: usize = 4;

impl Layout {
    /// The height of the page this layout draws with notes `band` tall
    /// and margin `mg`: the main view, the detail below it, the notes.
    fn height(&self, band: f64, mg: f64) -> f64 {
        let mut bottom = self.main.max().y;
        if let Some(d) = &self.detail {
            let scale = self.transform.scale();
            let frame = detail_frame(d, scale, &self.sizes, self.bearing.as_ref());
            let tall = (frame.max().y - frame.min().y) * scale * d.magnification;
            bottom += DETAIL_GAP + CAPTION + tall + NOTE_GAP;
        }
        bottom + band + mg
    }
}

/// The layout fitted to the pose of `ctx` with its notes' `band`.
fn fit(ctx: &LayerCtx, band: f64) -> Layout {
    let mut ctx = LayerCtx {
        sizes: Sizes::new(ctx.scene),
        ..*ctx
    };
    // The block and the arrows drawn to page lengths are sized at the
    // scale of the fit before: three fits bring the scale within a fraction
    // of a per cent of the last.
    for _ in 0..FITS - 1 {
        let (_, fit) = main_view(&ctx, band, fit::frame(&ctx));
        ctx.sizes = ctx.sizes.on_page(fit.scale(), ctx.scene.extremes());
    }
    let page = ctx.scene.page();
    let width = page.width() - 2.0 * page.margin();
    with_detail(&ctx, band, fit::frame(&ctx), |scale| {
        detail::detail(&ctx, scale, width)
    })
}

/// The layout whose main view is fitted to the world `frame` (with the
/// sizes of `ctx`), and the detail `details` gives at its scale; fitted
/// once more where the offset's dimension needs room beside the detail's
/// frame ([`beside_detail`]).
fn with_detail(
    ctx: &LayerCtx,
    band: f64,
    frame: Frame,
    details: impl Fn(f64) -> Option<detail::Detail>,
) -> Layout {
    let details = |scale: f64| {
        if ctx.scene.has_no_detail() {
            None
        } else {
            details(scale)
        }
    };
    let scene = ctx.scene;
    let block_ends = (scene.held_view().is_none() && scene.has(Layer::Mechanism)).then(|| {
        let (x, half) = (ctx.main.pose().a().x, ctx.sizes.block_half_length);
        (x - half, x + half)
    });
    let sizes = Sizes {
        block_ends,
        ..ctx.sizes
    };
    let (mut main, mut transform) = main_view(ctx, band, frame);
    let mut detail = details(transform.scale());
    let mut bearing = Bearing::of(ctx, &main, transform);
    let grown = beside_detail(
        ctx.scene,
        &sizes,
        frame,
        detail.as_ref(),
        transform.scale(),
        bearing.as_ref(),
    );
    if grown != frame {
        (main, transform) = main_view(ctx, band, grown);
        detail = details(transform.scale());
        bearing = Bearing::of(ctx, &main, transform);
    }
    Layout {
        sizes: Sizes {
            fitted: Some(grown),
            ..sizes
        },
        band,
        main,
        transform,
        detail,
        bearing,
    }
}

/// The layout held over the poses at `angles`: one fit to what the scene
/// draws at all of them but D (the union of their frames without it,
/// [`fit::frame_without_d`]; D off the page is drawn as an arrow at its
/// edge), the most notes of any,
/// and one detail showing the union of their details' regions at the least
/// of their magnifications, narrowed to the page if need be.
// cannot fail: one context per pose, and the held poses are at least one
// (`valid::held_view` refuses an empty list).
#[allow(clippy::indexing_slicing)]
pub(crate) fn held_view(scene: &Scene, angles: &[Angle]) -> Layout {
    let m = scene.mechanism();
    let poses: Vec<Constructions> = angles
        .iter()
        .map(|a| Constructions::new(m.pose(*a)))
        .collect();
    let mut ctxs: Vec<LayerCtx> = poses
        .iter()
        .map(|main| LayerCtx {
            scene,
            main,
            sizes: Sizes::new(scene),
            foot: None,
        })
        .collect();
    let band = ctxs.iter().map(|c| band(&notes(c))).fold(0.0, f64::max);
    // cannot fail: one context per pose, and a scene has at least one pose
    // (`valid::angles` refuses an empty list).
    #[allow(clippy::expect_used)]
    let union = |ctxs: &[LayerCtx]| {
        ctxs.iter()
            .map(fit::frame_without_d)
            .reduce(|a, b| Frame::new(a.min().inf(&b.min()), a.max().sup(&b.max())))
            .expect("at least one pose")
    };
    for _ in 0..FITS - 1 {
        let (_, fit) = main_view(&ctxs[0], band, union(&ctxs));
        let sizes = ctxs[0].sizes.on_page(fit.scale(), scene.extremes());
        for c in &mut ctxs {
            c.sizes = sizes;
        }
    }
    // The notes read at the page's scale (a polygon's side too short for
    // an arrow) may be more: room kept for them.
    let band = ctxs
        .iter()
        .map(|c| self::band(&notes(c)))
        .fold(band, f64::max);
    let page = scene.page();
    let width = page.width() - 2.0 * page.margin();
    with_detail(&ctxs[0], band, union(&ctxs), |scale| {
        let details: Vec<detail::Detail> = ctxs
            .iter()
            .filter_map(|c| detail::detail(c, scale, width))
            .collect();
        detail::union(&details, scale, width)
    })
}

/// The world `frame` of the main view grown on the side of the offset's
/// dimension (world −x, see [`dimensions::offset`]) to take in the frame
/// drawn on the main view round the region of `detail`: the dimension is
/// set beyond what the view was fitted to, and would otherwise run along
/// that frame's edge. The frame as it is without an offset, without a
/// detail, or where the detail's frame stays inside it.
fn beside_detail(
    scene: &Scene,
    sizes: &Sizes,
    frame: Frame,
    detail: Option<&detail::Detail>,
    scale: f64,
    bearing: Option<&Bearing>,
) -> Frame {
    let Some(d) = detail else {
        return frame;
    };
    if scene.mechanism().offset() == 0.0 || !scene.has(Layer::Mechanism) {
        return frame;
    }
    let left = detail_frame(d, scale, sizes, bearing).min().x;
    if left >= frame.min().x {
        return frame;
    }
    Frame::new(Point::new(left, frame.min().y), frame.max())
}

/// The constructions of the scene's own poses, the first drawn in full.
fn own_poses(scene: &Scene) -> Vec<Constructions> {
    let m = scene.mechanism();
    scene
        .angles()
        .iter()
        .map(|a| Constructions::new(m.pose(*a)))
        .collect()
}

/// Builds the figure of `scene` in `layout`: the one fitted to its own
/// pose ([`own`]) or one held over several ([`held_view`]).
pub(crate) fn build(scene: &Scene, layout: &Layout) -> (Figure, Evaluations) {
    let poses = own_poses(scene);
    // cannot fail: a scene is drawn only once `valid::scene` has passed it,
    // which refuses one without a pose.
    #[allow(clippy::indexing_slicing)]
    let mut ctx = LayerCtx {
        scene,
        main: &poses[0],
        sizes: Sizes::new(scene),
        foot: None,
    };

    // Notes first: their number of lines fixes the band below the panels.
    let notes = notes(&ctx);
    let own = band(&notes);
    let layout = *layout;
    ctx.sizes = layout.sizes;
    // The notes read again at the page's scale, which some of them speak
    // of (the polygons' vectors too short for an arrow); the band grows
    // where they are more than before it.
    let notes = self::notes(&ctx);
    let page = scene.page();
    // A pose outside a held range may have more notes than it left room
    // for, and the notes read at the page's scale more than those read
    // before it (a polygon's side too short for an arrow): the page grows
    // for them, the map stays.
    let band = own.max(self::band(&notes)).max(layout.band);
    let mg = page.margin();
    let (main, transform) = (layout.main, layout.transform);
    let detail = layout.detail;
    let bearing = layout.bearing.as_ref();
    let region = detail.map(|d| detail_frame(&d, transform.scale(), &layout.sizes, bearing));
    let mut canvas = main_canvas(&layout, region);
    // The bearing the layout kept the detail's frame off, where it found
    // one; found from the canvas alike.
    ctx.foot = Some(bearing.map_or_else(|| mechanism::foot(&ctx, &canvas), |b| b.foot));
    draw_layers(&ctx, &poses, &mut canvas, true);

    let mut bottom = main.max().y;
    let mut panels = Vec::new();
    if let (Some(d), Some(frame)) = (detail, region) {
        let panel = detail_panel(
            &ctx,
            &poses,
            &d,
            &frame,
            transform.scale(),
            bottom,
            page.width(),
        );
        let pose = ctx.main.pose();
        // The pins the detail was drawn for: at a high magnification the
        // frame's pad about them is less than a pin's radius on the main
        // view.
        let pins: Vec<Point> = [pose.a(), pose.b(), pose.c()]
            .into_iter()
            .filter(|p| d.region.contains(*p))
            .collect();
        let scales = (transform.scale(), transform.scale() * d.magnification);
        let mark = detail_mark(&frame, scales, bearing, &pins);
        mark_detail(&mut canvas, &mark, panel.rect(), d.magnification);
        bottom = panel.rect().max().y + NOTE_GAP;
        panels.push(panel);
    }
    let height = bottom + band + mg;
    push_notes(&mut canvas, Point::new(mg + 4.0, bottom + 4.0), notes);

    let mut evaluations = Evaluations::default();
    for p in &poses {
        evaluations.add(&p.evaluations());
    }
    let (items, points) = canvas.finish();
    let metadata = metadata(scene, points, &evaluations);
    panels.insert(0, Panel::new("panel-mechanism", main, transform, items));
    let figure = Figure::new(
        scene.name(),
        page.width(),
        height,
        scene.style(),
        scene.tolerance(),
        panels,
        metadata,
    )
    .with_font(scene.font())
    .with_size_unit(page.unit());
    let figure = match scene.title() {
        Some(t) => figure.with_title(t.clone()),
        None => figure,
    };
    (figure, evaluations)
}

/// Every layer of the scene, in order, on `canvas`; the scale notes only
/// when `notes` (the main view).
fn draw_layers(ctx: &LayerCtx, poses: &[Constructions], canvas: &mut Canvas, main: bool) {
    for layer in ctx.scene.layers() {
        canvas.set_hue(match layer {
            Layer::Velocity | Layer::Motion => Some(Hue::Velocity),
            l if l.is_acceleration() => Some(Hue::Acceleration),
            Layer::Torque => Some(Hue::Force),
            _ => None,
        });
        match layer {
            Layer::Mechanism => {
                mechanism::draw(ctx, poses.get(1..).unwrap_or_default(), canvas);
                if main {
                    dimensions::offset(ctx, canvas);
                }
            }
            Layer::Angles => dimensions::angles(ctx, canvas),
            Layer::Dimensions if main => dimensions::draw(ctx, canvas),
            Layer::Dimensions => {}
            Layer::Motion => motion::draw(ctx, canvas),
            Layer::Centrodes => curves::centrodes(ctx, canvas),
            Layer::Coupler => curves::coupler(ctx, canvas),
            Layer::Polar => curves::polar(ctx, canvas),
            Layer::VirtualCentres => centres::draw(ctx, canvas),
            Layer::Velocity => velocity::draw(ctx, canvas),
            Layer::Klein => acceleration::klein(ctx, canvas),
            Layer::Kisch => acceleration::kisch(ctx, canvas),
            Layer::Ritterhaus => acceleration::ritterhaus(ctx, canvas),
            Layer::Bennett => acceleration::bennett(ctx, canvas),
            Layer::Torque => torque::draw(ctx, canvas),
            // At their own scale: not in an enlarged detail.
            Layer::Polygons if main => polygons::draw(ctx, canvas),
            // The crank's ω in a crank's detail.
            Layer::Polygons => polygons::omega(ctx, canvas, true),
            Layer::Scales => {}
        }
    }
    canvas.set_hue(None);
}

/// The main view: the panel at the top of the page, as wide as the page
/// allows and only as tall as what it draws needs (the scene's page
/// height, less the notes' `band`, is the most it may take), and its map,
/// fitted to the `world` rectangle.
fn main_view(ctx: &LayerCtx, band: f64, world: Frame) -> (Frame, PageFromWorld) {
    let (panel, transform) = main_view_with(ctx, band, world, 0.0);
    let scene = ctx.scene;
    if !(scene.has(Layer::Dimensions) && dimensions::above(ctx)) {
        return (panel, transform);
    }
    // The dimensions stacked above the guides: the drawing moves down to
    // make room for them and the panel grows (the drawing keeps its
    // scale).
    let e = scene.mechanism().offset();
    let stroke = transform.apply(Point::new(0.0, e)).y;
    let top = stroke - transform.scale() * ctx.sizes.block_half_height - dimensions::DEPTH;
    let short = panel.min().y - top;
    if short <= 0.0 {
        return (panel, transform);
    }
    main_view_with(ctx, band, world, short + 2.0)
}

/// [`main_view`] with `room` page units more above the drawing, the
/// panel as much taller.
fn main_view_with(ctx: &LayerCtx, band: f64, world: Frame, room: f64) -> (Frame, PageFromWorld) {
    let scene = ctx.scene;
    let page = scene.page();
    let mg = page.margin();
    let inset = [INSET; 4]; // left, right, top, bottom
    let width = page.width() - 2.0 * mg;
    let fit_width = (width - inset[0] - inset[1]).max(20.0);
    let most = (page.height() - 2.0 * mg - band - inset[2] - inset[3]).max(20.0);
    let size = world.max() - world.min();
    let scale = (fit_width / size.x).min(most / size.y);
    let drawn = if scale.is_finite() && scale > 0.0 {
        (size.y * scale).max(20.0)
    } else {
        most
    };
    let mut panel = Frame::from_origin_size(mg, mg, width, drawn + inset[2] + inset[3] + room);
    let fit_rect = Frame::from_origin_size(mg + inset[0], mg + inset[2] + room, fit_width, drawn);
    // cannot fail: the fallback, a map of scale 1 between finite points,
    // is valid.
    #[allow(clippy::expect_used)]
    let transform = PageFromWorld::fit(&world, &fit_rect, scene.is_mirrored())
        .or_else(|| {
            PageFromWorld::uniform(1.0, scene.is_mirrored(), Point::origin(), panel.centre())
        })
        .expect("a unit map is valid");
    if scene.has(Layer::Dimensions) && !dimensions::above(ctx) {
        // The dimensions stacked below the guides: the panel grows to hold
        // them (the drawing keeps its scale).
        let e = scene.mechanism().offset();
        let stroke = transform.apply(Point::new(0.0, e)).y;
        let reach = stroke + transform.scale() * ctx.sizes.block_half_height + dimensions::DEPTH;
        let bottom = panel.max().y.max(reach);
        panel = Frame::from_corners(panel.min(), Point::new(panel.max().x, bottom));
    }
    (panel, transform)
}

/// The world frame a detail shows: its region with room for letters, at
/// least [`detail::MIN_HEIGHT`] page units tall.
/// An edge that would run within [`GUIDE_CLEAR`] of a guide (the world
/// heights `guides`) moves that far to whichever side of it is nearer,
/// but never nearer the detailed points than [`detail::PAD`] / 2, so
/// that the frame never reads as one more guide, cuts its hatching or
/// closes the channel with the block (a short rod's inner dead centre,
/// where the detail about C was just the guides' height), and what lay
/// outside the frame beyond a guide stays outside. An edge that runs
/// along the base of the crank centre's `bearing`, as the main view or
/// the detail draws it, moves off it ([`Bearing::kept_off`]): at Kisch's
/// l = 2.46 r, e = 0.861 r, 180° the frame's bottom edge was the
/// bearing's base line, the hatching hanging off the frame.
fn detail_frame(
    d: &detail::Detail,
    main_scale: f64,
    sizes: &Sizes,
    bearing: Option<&Bearing>,
) -> Frame {
    let guides = sizes.guide_heights();
    let scale = main_scale * d.magnification;
    let pad = detail::PAD / scale;
    let (lo, hi) = (d.region.min(), d.region.max());
    let grow = (0.5 * detail::MIN_HEIGHT / scale - 0.5 * (hi.y - lo.y) - pad).max(0.0);
    let (mut bottom, mut top) = (lo.y - pad - grow, hi.y + pad + grow);
    let (mut left, mut right) = (lo.x - pad, hi.x + pad);
    let keep = 0.5 * pad;
    // Clear of the guides' heights in the detail, and on the main view
    // where the guides run across the frame.
    let (g0, g1) = sizes.guides();
    let clear = match left < g1 && right > g0 {
        true => (GUIDE_CLEAR / scale).max(GUIDE_CLEAR_MAIN / main_scale),
        false => GUIDE_CLEAR / scale,
    };
    (bottom, top) = off_lines((bottom, top), (lo.y - keep, hi.y + keep), &guides, clear);
    // The sides off the block's ends, where the block runs across the
    // frame's height and the detail still fits the page's width.
    let across = |(y0, y1): (f64, f64)| bottom < y1 && top > y0;
    if let (Some(ends), Some(width)) = (sizes.block_ends, bearing.map(|b| b.width))
        && across((guides[0], guides[1]))
    {
        let clear = (BLOCK_CLEAR / scale).max(BLOCK_CLEAR_MAIN / main_scale);
        let inner = (lo.x - keep, hi.x + keep);
        let (l, r) = off_lines((left, right), inner, &[ends.0, ends.1], clear);
        if (r - l) * scale <= width {
            (left, right) = (l, r);
        }
    }
    let mut frame = Frame::new(Point::new(left, bottom), Point::new(right, top));
    if let Some(b) = bearing {
        let off_guides = |y: f64| guides.iter().all(|g| (y - g).abs() >= clear);
        let inner = Frame::new(
            Point::new(lo.x - keep, lo.y - keep),
            Point::new(hi.x + keep, hi.y + keep),
        );
        for s in [main_scale, scale] {
            frame = b.kept_off(frame, &inner, (s, scale), &off_guides);
        }
    }
    frame
}

/// A frame's near and far edges along one axis, `(near, far)`, each
/// moved off the `lines` it runs within `clear` of ([`off_band`]), its
/// inside kept to `(inner near, inner far)`; twice, as an edge moved off
/// one line may come near another.
fn off_lines(
    (mut near, mut far): (f64, f64),
    (inner_near, inner_far): (f64, f64),
    lines: &[f64],
    clear: f64,
) -> (f64, f64) {
    for _ in 0..2 {
        for &v in lines {
            far = off_band(far, inner_far, (v, v), clear);
            near = -off_band(-near, -inner_near, (-v, -v), clear);
        }
    }
    (near, far)
}

/// A frame's far edge at `edge` (its inside below it) moved off the band
/// `(a, b)` where it runs within `clear` of it: in to `a - clear` where
/// that is nearer than out to `b + clear` and keeps at or beyond
/// `inner` (the detailed points and room about them), else out. The
/// near edge is the same negated.
fn off_band(edge: f64, inner: f64, (a, b): (f64, f64), clear: f64) -> f64 {
    if edge <= a - clear || edge >= b + clear {
        return edge;
    }
    let (inward, outward) = (a - clear, b + clear);
    if inward >= inner && edge - inward < outward - edge {
        inward
    } else {
        outward
    }
}

impl Bearing {
    /// `frame` (a detail's, world) with its edges off the base of this
    /// bearing drawn at `scale` (the main view's or the detail's), the
    /// detail drawn at `detail`: an edge within [`BEARING_CLEAR`] of the
    /// base and its hatching, where it runs across them, moves out past
    /// them, on a page free to grow ([`Bearing::grows`]), where that
    /// grows the detail by at most [`MOST_FOR_BEARING`]
    /// or [`GROW_SHARE`] of its extent, and the sides then take in the base's ends where the detail still
    /// fits its width; else in, short of the base, where that keeps
    /// `inner` (the detailed points and room about them) inside; else
    /// it stays. No move lands an edge by a guide (`off_guides` of a
    /// height). A wall's base is moved out from only where the detail
    /// still fits its width (`self.width`, page units).
    fn kept_off(
        &self,
        frame: Frame,
        inner: &Frame,
        (scale, detail): (f64, f64),
        off_guides: &impl Fn(f64) -> bool,
    ) -> Frame {
        let (along_y, (a, b), (s0, s1)) = self.base(scale);
        let clear = BEARING_CLEAR / scale;
        let (lo, hi) = (frame.min(), frame.max());
        let extent = if along_y { hi.y - lo.y } else { hi.x - lo.x };
        let most = match self.grows {
            true => (MOST_FOR_BEARING / detail).max(GROW_SHARE * extent),
            false => f64::NEG_INFINITY,
        };
        // (near edge, far edge, inner near, inner far) along the base's
        // axis, and the stretch of the frame across it.
        let (near, far, inner_near, inner_far, across) = match along_y {
            true => (lo.y, hi.y, inner.min().y, inner.max().y, (lo.x, hi.x)),
            false => (lo.x, hi.x, inner.min().x, inner.max().x, (lo.y, hi.y)),
        };
        if s0 >= across.1 || s1 <= across.0 {
            return frame;
        }
        let ok = |v: f64| !along_y || off_guides(v);
        let moved = |grow: f64| {
            let far = moved_off(far, inner_far, (a, b), clear, grow, &ok);
            let near = -moved_off(-near, -inner_near, (-b, -a), clear, grow, &|v| ok(-v));
            (near, far)
        };
        // A wall's base is moved out from only where the detail still
        // fits its width.
        let (near, far) = match moved(most) {
            (n, f) if !along_y && (f - n) * detail > self.width => moved(f64::NEG_INFINITY),
            moved => moved,
        };
        let (mut x0, mut x1) = across;
        if along_y && near < a && b < far {
            let (w0, w1) = ((s0 - clear).min(x0), (s1 + clear).max(x1));
            let cheap = x0 - w0 <= most && w1 - x1 <= most;
            if cheap && (w1 - w0) * detail <= self.width {
                (x0, x1) = (w0, w1);
            }
        }
        match along_y {
            true => Frame::new(Point::new(x0, near), Point::new(x1, far)),
            false => Frame::new(Point::new(near, x0), Point::new(far, x1)),
        }
    }
}

/// [`Bearing::kept_off`]'s move of a far edge at `edge` off the band
/// `(a, b)`: out to `b + clear` where that grows by at most `grow`, else
/// in to `a - clear` where that keeps `inner` inside, each only where
/// `ok`; else where it is.
fn moved_off(
    edge: f64,
    inner: f64,
    (a, b): (f64, f64),
    clear: f64,
    grow: f64,
    ok: &impl Fn(f64) -> bool,
) -> f64 {
    if edge <= a - clear || edge >= b + clear {
        return edge;
    }
    let (inward, outward) = (a - clear, b + clear);
    if outward - edge <= grow && ok(outward) {
        outward
    } else if inward >= inner && ok(inward) {
        inward
    } else {
        edge
    }
}

/// The most a detail's frame grows (the detail's page units) to take
/// in the crank centre's bearing whose base it ran along
/// ([`Bearing::kept_off`]): beyond, it is brought in across the
/// pedestal (at ×10 the bearing drawn to the main view's sizes is a
/// tenth of a crank, and a detail grown to it showed mostly paper).
const MOST_FOR_BEARING: f64 = 72.0;

/// Where a bearing's pedestal begins, page units out from its centre:
/// past the pin's circle (4.2) and its line.
const PEDESTAL_FROM: f64 = 6.0;

/// The most a detail's frame grows to take in the bearing, as a share of
/// its extent along the base's axis, where that is more than
/// [`MOST_FOR_BEARING`].
const GROW_SHARE: f64 = 0.1;

/// The least distance, page units of the view that draws it (the main
/// view's or the detail's), between a detail's frame and the crank
/// centre's bearing's base or its hatching's far edge, where the frame
/// runs across them.
const BEARING_CLEAR: f64 = 5.0;

/// The least distance between a detail's frame and a guide along it,
/// page units: the guide's hatching (6.5 deep) and a clear gap.
const GUIDE_CLEAR: f64 = 14.0;

/// The least distance between a detail's frame drawn on the main view
/// and a guide along it, main view's page units: the hatching and a gap.
/// Held to [`GUIDE_CLEAR`] in the detail alone, the frame of a ×4 detail
/// stood 3.5 units off the guide on the main view, inside its hatching
/// (Kisch's construction at l = 1.08 r, 180°, the twenty-ninth review).
const GUIDE_CLEAR_MAIN: f64 = 10.0;

/// The least distance between a detail's side and an end of the slider
/// block, page units of the detail, and of the main view: a side within
/// it read as the block's edge drawn twice (Kisch's construction at
/// l = 1.08 r, 180°, its frame's left side 3 units off the block's on
/// the main view, the twenty-ninth review).
const BLOCK_CLEAR: f64 = 10.0;
const BLOCK_CLEAR_MAIN: f64 = 6.0;

/// The detail panel showing `frame` below `top`, centred on a page
/// `width` wide.
fn detail_panel(
    ctx: &LayerCtx,
    poses: &[Constructions],
    d: &detail::Detail,
    frame: &Frame,
    main_scale: f64,
    top: f64,
    width: f64,
) -> Panel {
    let scene = ctx.scene;
    let scale = main_scale * d.magnification;
    let size = (frame.max() - frame.min()) * scale;
    let rect = Frame::from_origin_size(
        0.5 * (width - size.x),
        top + DETAIL_GAP + CAPTION,
        size.x,
        size.y,
    );
    let centre = nalgebra::center(&frame.min(), &frame.max());
    // cannot fail: the scale is the main view's (finite and positive, as
    // `PageFromWorld::fit` made it) times one of the finite magnification
    // steps of `detail`, about the middle of a finite frame.
    #[allow(clippy::expect_used)]
    let transform = PageFromWorld::uniform(scale, scene.is_mirrored(), centre, rect.centre())
        .expect("a finite positive scale");
    let mut canvas = Canvas::new(transform, *frame).detail("detail-");
    draw_layers(ctx, poses, &mut canvas, false);
    let (mut items, _) = canvas.finish();
    joint::leave_out_along_links(&mut items, "detail-", scale);
    let notation = scene.notation();
    let results = [Named::VelocityPoint, Named::G].map(|p| notation.letter(p));
    joint::letter_near_together(&mut items, "detail-", scale, &results);
    Panel::new("panel-detail", rect, transform, items).clipped()
}

/// The scene's notes below its drawing, from `corner` down
/// (`note-scales`, [`Part::Notes`]); nothing without notes.
fn push_notes(canvas: &mut Canvas, corner: Point, notes: Vec<RichText>) {
    if notes.is_empty() {
        return;
    }
    canvas.with_part(Part::Notes, |canvas| {
        let lines = notes;
        canvas.push("note-scales", Role::Label, Shape::Note { corner, lines });
    });
}

/// The main view's canvas: where the `layout` has a detail of the world
/// `region`, the letters of the constructed points there are the
/// detail's, and with a crank's detail the marks about the crank too.
fn main_canvas(layout: &Layout, region: Option<Frame>) -> Canvas {
    let transform = layout.transform;
    let canvas = Canvas::new(transform, transform.world_frame(&layout.main));
    match (region, layout.detail) {
        (Some(frame), Some(d)) if d.focus == detail::Focus::Crank => {
            canvas.quiet(frame).bare(frame)
        }
        (Some(frame), Some(_)) => canvas.quiet(frame),
        _ => canvas,
    }
}

/// The frame on the main view matching the detail, with its
/// magnification beside it; the detail's border and caption (drawn by the
/// main view, so that the detail's clip leaves them whole). All are
/// [`Part::DetailMark`]s.
fn mark_detail(canvas: &mut Canvas, frame: &Frame, rect: &Frame, magnification: f64) {
    canvas.with_part(Part::DetailMark, |canvas| {
        detail_marks(canvas, frame, rect, magnification);
    });
}

/// The box marking on the main view (drawn at `scale`, the detail at
/// `detail`) the detail's
/// `frame`: the frame, grown where a side of it is under [`MARK_SLIM`]
/// about its middle to [`MARK_LEAST`] a side, and where an edge runs
/// through the circle of one of the mechanism's `pins` (those the detail
/// enlarges)
/// ([`MARK_THROUGH_PIN`]), out past the pin by [`MARK_PIN_CLEAR`]; then kept off the crank centre's
/// `bearing` ([`Bearing::kept_off`], grown past it by up to
/// [`MOST_FOR_BEARING`] main view units where the box stays under
/// [`MARK_MOST`] a side). At a long rod the frame about the
/// crank, a few units wider than the crank pin and the crank centre's
/// pin, hugged both, or ran along the rod through both: three reviewers
/// read it as a slotted link. The frame as it is where nothing grows it.
fn detail_mark(
    frame: &Frame,
    (scale, detail): (f64, f64),
    bearing: Option<&Bearing>,
    pins: &[Point],
) -> Frame {
    let least = match frame.width().min(frame.height()) * scale < MARK_SLIM {
        true => MARK_LEAST / scale,
        false => 0.0,
    };
    let half = Vector::new(frame.width().max(least), frame.height().max(least)) * 0.5;
    let (mut lo, mut hi) = (frame.centre() - half, frame.centre() + half);
    let (clear, through) = (MARK_PIN_CLEAR / scale, MARK_THROUGH_PIN / scale);
    for p in pins {
        // Each edge running through the pin's circle moves out past it.
        let (near, far) = (p - lo, hi - p);
        if near.x < through {
            lo.x = p.x - clear;
        }
        if near.y < through {
            lo.y = p.y - clear;
        }
        if far.x < through {
            hi.x = p.x + clear;
        }
        if far.y < through {
            hi.y = p.y + clear;
        }
    }
    let mark = Frame::new(lo, hi);
    if mark == *frame {
        return mark;
    }
    let Some(b) = bearing else {
        return mark;
    };
    // Grown past the bearing as the main view draws it where the box
    // stays small (a long rod's crank and its bearing boxed together),
    // else by no more than the detail's frame would be.
    let wide = b.kept_off(mark, frame, (scale, scale), &|_| true);
    match (wide.max() - wide.min()).max() * scale < MARK_MOST {
        true => wide,
        false => b.kept_off(mark, frame, (scale, detail), &|_| true),
    }
}

/// The least side (page units) of the box marking a detail on the main
/// view: the crank centre's pin (4.2 units), a pin's width clear of it
/// each side of the crank of a long rod.
const MARK_LEAST: f64 = 28.0;

/// The side (page units) under which a detail's frame on the main view
/// is a slim box that reads as a link: a pin's width (8.4) and its pen
/// and a gap each side.
const MARK_SLIM: f64 = 14.0;

/// The least distance (page units) between the box marking a detail on
/// the main view and a pin of the mechanism inside it: its circle (4.2)
/// and a gap.
const MARK_PIN_CLEAR: f64 = 7.0;

/// The distance (page units) from a pin's centre within which an edge
/// of the box marking a detail runs through the pin's circle (4.2) and
/// pen.
const MARK_THROUGH_PIN: f64 = 5.0;

/// The most side (page units) of a detail's box on the main view grown
/// past the crank centre's bearing by the main view's units: the side
/// under which two joints in it are lettered in the detail alone
/// ([`SMALL_DETAIL_EMS`] at a point's letter size; grown past the
/// bearing at Fig. 67, l = 1.1 r, e = 0.08 r, 210°, the box reached 69
/// units and C and A were lettered on the main view again, crowded).
const MARK_MOST: f64 = SMALL_DETAIL_EMS * LETTER_SIZE;

/// [`mark_detail`]'s items.
fn detail_marks(canvas: &mut Canvas, frame: &Frame, rect: &Frame, magnification: f64) {
    let (lo, hi) = (frame.min(), frame.max());
    let x = crate::number::short(magnification);
    canvas.push(
        "detail-frame",
        Role::Frame,
        Shape::Polyline {
            points: vec![lo, Point::new(hi.x, lo.y), hi, Point::new(lo.x, hi.y)],
            closed: true,
        },
    );
    canvas.label(
        "label-detail",
        Point::new(lo.x, hi.y),
        RichText::parse(&format!("×{x}")),
        TextSize::Small,
    );
    let t = *canvas.transform();
    let (x0, y0) = (rect.min().x, rect.min().y);
    let (x1, y1) = (rect.max().x, rect.max().y);
    let border = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
        .map(|(x, y)| t.invert(Point::new(x, y)))
        .to_vec();
    canvas.push(
        "detail-border",
        Role::Frame,
        Shape::Polyline {
            points: border,
            closed: true,
        },
    );
    canvas.push(
        "detail-caption",
        Role::Label,
        Shape::Text {
            at: t.invert(Point::new(x0, y0)),
            offset: Vector::new(0.0, -0.5 * CAPTION),
            text: RichText::parse(&format!("Detail ×{x}")),
            align: Align::Start,
            size: TextSize::Small,
        },
    );
}

/// The caption line (markup) that names a non-zero offset.
pub(crate) fn offset_note(scene: &Scene) -> String {
    let e = scene.mechanism().offset();
    let (c, side) = (
        scene.notation().letter(Named::CrankCentre),
        if e > 0.0 { "above" } else { "below" },
    );
    format!(
        "Offset engine: the line of stroke is *e* = {} {} {side} the crank centre *{c}*.",
        crate::number::sig(e.abs()),
        scene.units().length()
    )
}

fn metadata(scene: &Scene, points: Map<String, Value>, ev: &Evaluations) -> Metadata {
    let m = scene.mechanism();
    let mut meta = Metadata::new();
    meta.set_engine(EngineRecord {
        crank: round(m.crank()),
        rod: round(m.rod()),
        offset: round(m.offset()),
        unit: scene.units().length().to_string(),
    });
    if let Some(first) = scene.angles().first() {
        meta.set_angle_deg(round(first.degrees()));
    }
    if scene.angles().len() > 1 {
        let all: Vec<f64> = scene.angles().iter().map(|a| round(a.degrees())).collect();
        meta.insert("angles_deg", json!(all));
    }
    meta.set_omega(round(scene.omega()));
    meta.insert(
        "layers",
        json!(scene.layers().iter().map(|l| l.name()).collect::<Vec<_>>()),
    );
    meta.insert("notation", json!(scene.notation().name()));
    meta.insert("mirrored", json!(scene.is_mirrored()));
    meta.insert("points", Value::Object(points));
    meta.insert(
        "evaluations",
        serde_json::to_value(ev).unwrap_or(Value::Null),
    );
    meta
}
