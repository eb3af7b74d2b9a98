//! A figure's SVG read back as a plate: the page, its panels with their
//! links, guides, lines, labels and point markers in page coordinates, and
//! the ink box of everything drawn. Only the SVG text is read (ids,
//! classes, each panel's `data-page-from-world`, the metadata); geometry
//! and the glyph boxes of labels come from usvg, which lays the text out
//! with the fonts of [`font_database`].

use crate::common::metadata;
use resvg::usvg;
use std::collections::HashMap;
use std::sync::Arc;

/// A point on the page.
pub type Pt = (f64, f64);

/// A straight piece of a drawn line, in page coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Seg(pub Pt, pub Pt);

/// An axis-aligned box in page coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rect {
    pub x0: f64,
    pub y0: f64,
    pub x1: f64,
    pub y1: f64,
}

/// A line drawn in a panel: its element's id and class, and its pieces.
#[derive(Debug, Clone)]
pub struct Stroke {
    pub id: String,
    pub class: String,
    pub segs: Vec<Seg>,
}

/// A `<text class="label">`: its id, the box of its glyphs and its size.
#[derive(Debug, Clone)]
pub struct Label {
    pub id: String,
    pub rect: Rect,
    pub font_size: f64,
}

/// A panel `<g>` with `data-page-from-world`.
#[derive(Debug, Clone, Default)]
pub struct Panel {
    pub id: String,
    /// Prefix of the ids inside it: `detail-` in a detail panel.
    pub prefix: String,
    /// x' = a x + c y + e, y' = b x + d y + f as [a, b, c, d, e, f].
    pub page_from_world: [f64; 6],
    pub strokes: Vec<Stroke>,
    pub labels: Vec<Label>,
    /// Point markers (`point-X`) by their letter `X`: the marker's centre.
    pub markers: HashMap<String, Pt>,
}

/// What a figure's SVG draws, as far as the plate check needs it.
#[derive(Debug, Clone, Default)]
pub struct Plate {
    pub width: f64,
    pub height: f64,
    /// The mechanism panels: `panel-mechanism` and any `panel-detail…`.
    pub panels: Vec<Panel>,
    /// Labels outside the mechanism and diagram panels (notes).
    pub page_labels: Vec<Label>,
    /// Every text of the figure, whatever its panel or class (ticks,
    /// titles, captions, legends, letters, notes), clipped as drawn, its
    /// size in px as written (the size times the text's scale).
    pub texts: Vec<Label>,
    /// The ink box of every element drawn, with its id (or its nearest
    /// ancestor's).
    pub ink: Vec<(String, Rect)>,
    /// The metadata `points`, in world coordinates.
    pub world_points: HashMap<String, Pt>,
    /// The diagram panels that draw a polygon (an id holding `polygon`):
    /// their point markers by letter (after any prefix, `detail-point-k`
    /// as `k`) and their letters.
    pub polygons: Vec<Panel>,
}

/// The fonts labels are laid out with: the one place to change when the
/// figures bundle their fonts (load those faces' data here instead of the
/// system's). The system's font files are read into memory once, so that
/// laying out thousands of labels does not map them again each time.
pub fn font_database() -> Arc<usvg::fontdb::Database> {
    // The bundled faces only: the type the program itself draws with.
    slider_crank::render::font_database()
}

impl Rect {
    fn from_usvg(r: usvg::Rect) -> Self {
        Rect {
            x0: r.left() as f64,
            y0: r.top() as f64,
            x1: r.right() as f64,
            y1: r.bottom() as f64,
        }
    }

    /// The smallest box around `points`.
    pub fn around(points: impl IntoIterator<Item = Pt>) -> Option<Self> {
        points.into_iter().fold(None, |r, (x, y)| {
            Some(match r {
                None => Rect {
                    x0: x,
                    y0: y,
                    x1: x,
                    y1: y,
                },
                Some(r) => Rect {
                    x0: r.x0.min(x),
                    y0: r.y0.min(y),
                    x1: r.x1.max(x),
                    y1: r.y1.max(y),
                },
            })
        })
    }

    /// The box moved inwards by `d` on every side (outwards for d < 0).
    pub fn shrunk(&self, d: f64) -> Rect {
        Rect {
            x0: self.x0 + d,
            y0: self.y0 + d,
            x1: self.x1 - d,
            y1: self.y1 - d,
        }
    }

    /// The common part of two boxes, if any.
    pub fn intersection(&self, o: &Rect) -> Option<Rect> {
        let r = Rect {
            x0: self.x0.max(o.x0),
            y0: self.y0.max(o.y0),
            x1: self.x1.min(o.x1),
            y1: self.y1.min(o.y1),
        };
        (r.x0 <= r.x1 && r.y0 <= r.y1).then_some(r)
    }

    /// Whether the boxes share an area (not merely an edge).
    pub fn overlaps(&self, o: &Rect) -> bool {
        self.x0 < o.x1 && o.x0 < self.x1 && self.y0 < o.y1 && o.y0 < self.y1
    }

    /// Whether `o` lies inside this box.
    pub fn contains(&self, o: &Rect) -> bool {
        o.x0 >= self.x0 && o.y0 >= self.y0 && o.x1 <= self.x1 && o.y1 <= self.y1
    }

    /// Distance from `p` to the nearest point of the box (0 inside).
    pub fn distance_to(&self, p: Pt) -> f64 {
        let dx = (self.x0 - p.0).max(p.0 - self.x1).max(0.0);
        let dy = (self.y0 - p.1).max(p.1 - self.y1).max(0.0);
        dx.hypot(dy)
    }

    /// The distance from the box to the segment `s` (0 where it enters
    /// the box).
    pub fn distance_to_seg(&self, s: &Seg) -> f64 {
        if self.clip(s).is_some() {
            return 0.0;
        }
        let corners = [
            (self.x0, self.y0),
            (self.x1, self.y0),
            (self.x1, self.y1),
            (self.x0, self.y1),
        ];
        let ends = [self.distance_to(s.0), self.distance_to(s.1)];
        (corners.iter().map(|&c| s.distance_to(c)))
            .chain(ends)
            .fold(f64::INFINITY, f64::min)
    }

    /// The larger side.
    pub fn span(&self) -> f64 {
        (self.x1 - self.x0).max(self.y1 - self.y0)
    }

    /// The part of `s` inside the box (Liang–Barsky), if any.
    pub fn clip(&self, s: &Seg) -> Option<Seg> {
        let Seg((x0, y0), (x1, y1)) = *s;
        let (dx, dy) = (x1 - x0, y1 - y0);
        let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
        for (p, q) in [
            (-dx, x0 - self.x0),
            (dx, self.x1 - x0),
            (-dy, y0 - self.y0),
            (dy, self.y1 - y0),
        ] {
            if p == 0.0 {
                if q < 0.0 {
                    return None;
                }
            } else if p < 0.0 {
                t0 = t0.max(q / p);
            } else {
                t1 = t1.min(q / p);
            }
        }
        (t0 <= t1).then_some(Seg(
            (x0 + t0 * dx, y0 + t0 * dy),
            (x0 + t1 * dx, y0 + t1 * dy),
        ))
    }
}

impl Seg {
    fn length(&self) -> f64 {
        (self.1.0 - self.0.0).hypot(self.1.1 - self.0.1)
    }

    /// The distance from `p` to the segment.
    pub fn distance_to(&self, p: Pt) -> f64 {
        crate::common::segment_distance(p, self.0, self.1)
    }

    /// The segment with `d` taken off each end (a point if shorter than 2d).
    pub fn trimmed(&self, d: f64) -> Seg {
        let len = self.length();
        let t = if len > 2.0 * d { d / len } else { 0.5 };
        let at = |t: f64| {
            (
                self.0.0 + t * (self.1.0 - self.0.0),
                self.0.1 + t * (self.1.1 - self.0.1),
            )
        };
        Seg(at(t), at(1.0 - t))
    }

    /// Whether the two closed segments share a point.
    pub fn meets(&self, o: &Seg) -> bool {
        let (d1, d2) = (orient(o.0, o.1, self.0), orient(o.0, o.1, self.1));
        let (d3, d4) = (orient(self.0, self.1, o.0), orient(self.0, self.1, o.1));
        if d1 * d2 < 0.0 && d3 * d4 < 0.0 {
            return true;
        }
        (d1 == 0.0 && within(o, self.0))
            || (d2 == 0.0 && within(o, self.1))
            || (d3 == 0.0 && within(self, o.0))
            || (d4 == 0.0 && within(self, o.1))
    }
}

/// Twice the signed area of the triangle abc.
fn orient(a: Pt, b: Pt, c: Pt) -> f64 {
    (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0)
}

/// Whether `p`, on the line of `s`, lies within its extent.
fn within(s: &Seg, p: Pt) -> bool {
    p.0 >= s.0.0.min(s.1.0)
        && p.0 <= s.0.0.max(s.1.0)
        && p.1 >= s.0.1.min(s.1.1)
        && p.1 <= s.0.1.max(s.1.1)
}

/// `[a, b, c, d, e, f]` from the text of `data-page-from-world`.
pub fn parse_affine(text: &str) -> Option<[f64; 6]> {
    let v: Vec<f64> = text
        .split_whitespace()
        .map(|t| t.parse().ok())
        .collect::<Option<_>>()?;
    v.try_into().ok()
}

/// World point `p` mapped by `[a, b, c, d, e, f]`.
pub fn apply(m: &[f64; 6], p: Pt) -> Pt {
    (
        m[0] * p.0 + m[2] * p.1 + m[4],
        m[1] * p.0 + m[3] * p.1 + m[5],
    )
}

/// Where a drawn element belongs.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Place {
    /// Inside the mechanism panel of this index in [`Plate::panels`].
    Mechanism(usize),
    /// Outside every panel, or in the notes panel.
    Page,
    /// Inside the polygon panel of this index in [`Plate::polygons`].
    Polygon(usize),
    /// Inside a diagram panel (plots): only its ink counts.
    Diagram,
}

/// What the walk over the usvg tree carries down from the groups.
#[derive(Debug, Clone)]
struct Context {
    place: Place,
    /// The id of the nearest element with one (for id-less children).
    owner: String,
    /// The clip box of the nearest clipped group, in page coordinates.
    clip: Option<Rect>,
}

impl Plate {
    /// Reads `svg`; panics if usvg cannot parse it.
    pub fn read(svg: &str) -> Plate {
        let options = usvg::Options {
            fontdb: font_database(),
            ..usvg::Options::default()
        };
        let tree = usvg::Tree::from_str(svg, &options).expect("the SVG parses");
        let mut plate = Plate {
            width: tree.size().width() as f64,
            height: tree.size().height() as f64,
            world_points: world_points(svg),
            ..Plate::default()
        };
        let top = Context {
            place: Place::Page,
            owner: String::new(),
            clip: None,
        };
        plate.walk(&Tags::of(svg), tree.root(), &top);
        plate
    }

    /// The page box, `0 0 width height`.
    pub fn page(&self) -> Rect {
        Rect {
            x0: 0.0,
            y0: 0.0,
            x1: self.width,
            y1: self.height,
        }
    }

    fn walk(&mut self, tags: &Tags, group: &usvg::Group, ctx: &Context) {
        for node in group.children() {
            let ctx = self.enter(tags, node, ctx);
            match node {
                usvg::Node::Group(g) => self.walk(tags, g, &ctx),
                usvg::Node::Path(p) => self.add_path(tags, p, &ctx),
                usvg::Node::Text(t) => self.add_text(tags, t, &ctx),
                usvg::Node::Image(i) => self.add_ink(&ctx, Rect::from_usvg(i.abs_bounding_box())),
            }
        }
    }

    /// The context inside `node`: a panel group starts a new place, a
    /// clipped group narrows the clip, an id becomes the owner.
    fn enter(&mut self, tags: &Tags, node: &usvg::Node, ctx: &Context) -> Context {
        let mut inner = ctx.clone();
        let id = node.id();
        if id.is_empty() {
            return inner;
        }
        inner.owner = id.to_string();
        if let usvg::Node::Group(g) = node {
            if let Some(m) = tags
                .attr(id, "data-page-from-world")
                .and_then(|t| parse_affine(&t))
            {
                inner.place = self.panel_place(id, m);
            }
            if let Some(c) = g.clip_path() {
                let r = clip_box(g, c);
                inner.clip = Some(ctx.clip.and_then(|o| o.intersection(&r)).unwrap_or(r));
            }
        }
        inner
    }

    fn panel_place(&mut self, id: &str, page_from_world: [f64; 6]) -> Place {
        if id == "panel-notes" {
            return Place::Page;
        }
        if id.contains("polygon") {
            self.polygons.push(Panel {
                id: id.to_string(),
                page_from_world,
                ..Panel::default()
            });
            return Place::Polygon(self.polygons.len() - 1);
        }
        let detail = id.starts_with("panel-detail");
        if id != "panel-mechanism" && !detail {
            return Place::Diagram;
        }
        let prefix = if detail { "detail-" } else { "" };
        self.panels.push(Panel {
            id: id.to_string(),
            prefix: prefix.to_string(),
            page_from_world,
            ..Panel::default()
        });
        Place::Mechanism(self.panels.len() - 1)
    }

    fn add_ink(&mut self, ctx: &Context, r: Rect) {
        let r = match ctx.clip {
            Some(c) => match c.intersection(&r) {
                Some(r) => r,
                None => return,
            },
            None => r,
        };
        self.ink.push((ctx.owner.clone(), r));
    }

    fn add_path(&mut self, tags: &Tags, path: &usvg::Path, ctx: &Context) {
        self.add_ink(ctx, Rect::from_usvg(path.abs_stroke_bounding_box()));
        if let Place::Polygon(i) = ctx.place
            && let Some((_, letter)) = ctx.owner.split_once("point-")
        {
            let b = Rect::from_usvg(path.abs_bounding_box());
            let centre = ((b.x0 + b.x1) / 2.0, (b.y0 + b.y1) / 2.0);
            let markers = &mut self.polygons[i].markers;
            markers.entry(letter.to_string()).or_insert(centre);
        }
        let Place::Mechanism(i) = ctx.place else {
            return;
        };
        let segs = flatten(path.data(), path.abs_transform());
        let segs = match ctx.clip {
            Some(c) => segs.iter().filter_map(|s| c.clip(s)).collect(),
            None => segs,
        };
        let class = tags.class(&ctx.owner);
        let panel = &mut self.panels[i];
        if let Some(letter) = ctx.owner.strip_prefix(&format!("{}point-", panel.prefix)) {
            let b = Rect::from_usvg(path.abs_bounding_box());
            let centre = ((b.x0 + b.x1) / 2.0, (b.y0 + b.y1) / 2.0);
            panel.markers.entry(letter.to_string()).or_insert(centre);
        }
        panel.strokes.push(Stroke {
            id: ctx.owner.clone(),
            class,
            segs,
        });
    }

    fn add_text(&mut self, tags: &Tags, text: &usvg::Text, ctx: &Context) {
        let glyphs = text.flattened().abs_bounding_box();
        let rect = Rect::from_usvg(glyphs);
        self.add_ink(ctx, rect);
        let rect = match ctx.clip {
            Some(c) => match c.intersection(&rect) {
                Some(r) => r,
                None => return,
            },
            None => rect,
        };
        let font_size = text
            .chunks()
            .first()
            .and_then(|c| c.spans().first())
            .map_or(16.0, |s| s.font_size().get() as f64);
        let ts = text.abs_transform();
        let scale = ((ts.sx * ts.sy - ts.kx * ts.ky).abs() as f64).sqrt();
        self.texts.push(Label {
            id: ctx.owner.clone(),
            rect,
            font_size: font_size * scale,
        });
        if tags.class(&ctx.owner) != "label" {
            return;
        }
        let label = Label {
            id: ctx.owner.clone(),
            rect,
            font_size,
        };
        match ctx.place {
            Place::Mechanism(i) => self.panels[i].labels.push(label),
            Place::Page => self.page_labels.push(label),
            Place::Polygon(i) => self.polygons[i].labels.push(label),
            Place::Diagram => {}
        }
    }

    /// Where point `letter` is drawn in `panel`: its marker, else the
    /// metadata point mapped through the panel's `data-page-from-world`.
    pub fn point(&self, panel: &Panel, letter: &str) -> Option<Pt> {
        panel.markers.get(letter).copied().or_else(|| {
            self.world_points
                .get(letter)
                .map(|p| apply(&panel.page_from_world, *p))
        })
    }
}

/// The start tag of every element with an id, read once per plate (a
/// search of the whole SVG for each element's attributes cost a tenth of
/// the plate sweep): the first tag with each id, as `common::tag` finds.
struct Tags<'a>(HashMap<&'a str, &'a str>);

impl<'a> Tags<'a> {
    fn of(svg: &'a str) -> Self {
        let mut tags = HashMap::new();
        let mut from = 0;
        while let Some(at) = svg[from..].find("id=\"").map(|i| from + i) {
            let value = at + "id=\"".len();
            from = value;
            let (Some(len), Some(start), Some(end)) = (
                svg[value..].find('"'),
                svg[..at].rfind('<'),
                svg[at..].find('>').map(|e| at + e),
            ) else {
                continue;
            };
            tags.entry(&svg[value..value + len])
                .or_insert(&svg[start..end]);
        }
        Tags(tags)
    }

    /// The text of attribute `name` of the element with `id`.
    fn attr(&self, id: &str, name: &str) -> Option<String> {
        let t = self.0.get(id)?;
        let key = format!(" {name}=\"");
        let v = t.find(&key)? + key.len();
        Some(t[v..v + t[v..].find('"')?].to_string())
    }

    /// The class of the element with `id` ("" without one).
    fn class(&self, id: &str) -> String {
        if id.is_empty() {
            return String::new();
        }
        self.attr(id, "class").unwrap_or_default()
    }
}

/// The metadata `points` that are finite pairs.
fn world_points(svg: &str) -> HashMap<String, Pt> {
    if !svg.contains("<metadata>") {
        return HashMap::new();
    }
    let meta = metadata(svg);
    let Some(points) = meta.get("points").and_then(|p| p.as_object()) else {
        return HashMap::new();
    };
    points
        .iter()
        .filter_map(|(k, v)| Some((k.clone(), (v.get(0)?.as_f64()?, v.get(1)?.as_f64()?))))
        .collect()
}

/// The page box of clip path `clip` applied to group `g`.
fn clip_box(g: &usvg::Group, clip: &usvg::ClipPath) -> Rect {
    let to_page = g.abs_transform().pre_concat(clip.transform());
    let mut corners = Vec::new();
    collect_corners(clip.root(), to_page, &mut corners);
    Rect::around(corners).unwrap_or(Rect {
        x0: 0.0,
        y0: 0.0,
        x1: 0.0,
        y1: 0.0,
    })
}

fn collect_corners(group: &usvg::Group, to_page: usvg::Transform, out: &mut Vec<Pt>) {
    for node in group.children() {
        match node {
            usvg::Node::Group(g) => collect_corners(g, to_page, out),
            usvg::Node::Path(p) => {
                let b = p.data().bounds();
                let ts = to_page.pre_concat(p.abs_transform());
                for (x, y) in [
                    (b.left(), b.top()),
                    (b.right(), b.top()),
                    (b.left(), b.bottom()),
                    (b.right(), b.bottom()),
                ] {
                    out.push(map(ts, x, y));
                }
            }
            _ => {}
        }
    }
}

fn map(ts: usvg::Transform, x: f32, y: f32) -> Pt {
    let mut p = usvg::tiny_skia_path::Point::from_xy(x, y);
    ts.map_point(&mut p);
    (p.x as f64, p.y as f64)
}

/// Pieces of a Bézier curve when flattened.
const CURVE_PIECES: usize = 12;

/// The path as straight pieces in page coordinates (curves flattened).
fn flatten(data: &usvg::tiny_skia_path::Path, ts: usvg::Transform) -> Vec<Seg> {
    use usvg::tiny_skia_path::PathSegment as S;
    let mut segs = Vec::new();
    let (mut start, mut at) = ((0.0, 0.0), (0.0, 0.0));
    for seg in data.segments() {
        let next = match seg {
            S::MoveTo(p) => {
                start = map(ts, p.x, p.y);
                at = start;
                continue;
            }
            S::LineTo(p) => vec![map(ts, p.x, p.y)],
            S::QuadTo(c, p) => bezier(&[at, map(ts, c.x, c.y), map(ts, p.x, p.y)]),
            S::CubicTo(c1, c2, p) => bezier(&[
                at,
                map(ts, c1.x, c1.y),
                map(ts, c2.x, c2.y),
                map(ts, p.x, p.y),
            ]),
            S::Close => vec![start],
        };
        for p in next {
            segs.push(Seg(at, p));
            at = p;
        }
    }
    segs
}

/// Points along the Bézier curve with control points `ctrl` (de Casteljau),
/// after the first.
fn bezier(ctrl: &[Pt]) -> Vec<Pt> {
    (1..=CURVE_PIECES)
        .map(|i| {
            let t = i as f64 / CURVE_PIECES as f64;
            let mut p = ctrl.to_vec();
            while p.len() > 1 {
                p = p
                    .windows(2)
                    .map(|w| {
                        (
                            w[0].0 + t * (w[1].0 - w[0].0),
                            w[0].1 + t * (w[1].1 - w[0].1),
                        )
                    })
                    .collect();
            }
            p[0]
        })
        .collect()
}
