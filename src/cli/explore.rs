//! `slider-crank explore`: the explorer's page served on the loopback
//! address. A request for a figure is a `figure` command: its query is
//! turned into the flags of `figure NAME` and read by the same parser and
//! checks ([`super::figure::options`]); a handout's, into those of
//! `handout`. Only the flags listed here are taken: none that reads or
//! writes a file.

use super::figure::{FigureFlags, options};
use super::handout::{HandoutArgs, template};
use super::output::Stdout;
use clap::{Args, Parser};
use slider_crank::catalogue::FigureOptions;
use slider_crank::explore::{Explorer, Refusal, Reply, Request, WORKER, page};
use slider_crank::render::{FileFormat, to_svg, to_svg_with_fonts};
use slider_crank::{Angle, Error, Figure, FigureName, Result, SliderCrank, rpm_to_omega};
use std::sync::Arc;

/// Serve the explorer on the loopback address.
#[derive(Debug, Args)]
pub struct ExploreArgs {
    // The help lists every named figure by its group.
    #[arg(
        value_name = "NAME",
        default_value = "fig-66-kisch",
        help = super::figure::names_help(&slider_crank::catalogue::Group::ALL, "The figure the page opens on")
    )]
    pub name: FigureName,
    /// The port on 127.0.0.1 and ::1 (never another address); 0 takes a
    /// free port, printed with the address
    #[arg(long, value_name = "P", default_value_t = DEFAULT_PORT)]
    pub port: u16,
}

/// The port the explorer listens on unless told.
pub const DEFAULT_PORT: u16 = 8744;

/// A figure request: `figure NAME` and its flags, as the command line reads them.
#[derive(Debug, Parser)]
#[command(name = "figure", no_binary_name = true)]
struct FigureRequest {
    name: FigureName,
    #[command(flatten)]
    flags: FigureFlags,
}

/// A handout request: the flags of `handout` for one engine.
#[derive(Debug, Parser)]
#[command(name = "handout", no_binary_name = true)]
struct HandoutRequest {
    #[command(flatten)]
    args: HandoutArgs,
}

/// The flags of `figure` a figure request may give, by their names in
/// the query (`mirror` is `true` or `false`; `name` is the figure).
const FIGURE_FLAGS: [&str; 15] = [
    "crank",
    "rod",
    "offset",
    "angle",
    "rpm",
    "omega",
    "layers",
    "style",
    "font",
    "notation",
    "unit",
    "force-unit",
    "mass",
    "fluctuation",
    "fit",
];

/// The flags of `handout` a handout request may give.
const HANDOUT_FLAGS: [&str; 11] = [
    "crank",
    "rod",
    "offset",
    "angle",
    "rpm",
    "omega",
    "unit",
    "force-unit",
    "torque",
    "friction",
    "paper",
];

/// The query as command-line flags (`--rod=2.5`), every name checked
/// against `allowed`; a value is one argument whatever it holds.
fn flags(request: &Request, allowed: &[&str]) -> std::result::Result<Vec<String>, Refusal> {
    let mut argv = Vec::new();
    for (name, value) in request.query() {
        match name.as_str() {
            "name" | "format" => {}
            "mirror" => argv.push(match value.as_str() {
                "true" => "--mirror".to_string(),
                "false" => "--no-mirror".to_string(),
                _ => return Err(Refusal::new(400, "mirror is true or false")),
            }),
            "data" | "out" => {
                return Err(Refusal::new(
                    400,
                    &format!("{name}: the explorer reads and writes no file"),
                ));
            }
            known if allowed.contains(&known) => argv.push(format!("--{known}={value}")),
            other => {
                return Err(Refusal::new(
                    400,
                    &format!(
                        "unknown value '{}' (the request takes name, {}, mirror)",
                        Error::show(other),
                        allowed.join(", ")
                    ),
                ));
            }
        }
    }
    Ok(argv)
}

/// The first line of clap's message, as the command line says it.
fn clap_refusal(e: &clap::Error) -> Refusal {
    let text = e.render().to_string();
    let line = text
        .lines()
        .map(str::trim)
        .find(|l| !l.is_empty())
        .unwrap_or("invalid request");
    let line: String = line
        .trim_start_matches("error: ")
        .chars()
        .take(300)
        .collect();
    Refusal::new(422, &line)
}

/// The figure the request asks for, read as `figure NAME FLAGS`.
fn figure_request(
    request: &Request,
    initial: FigureName,
) -> std::result::Result<FigureRequest, Refusal> {
    let name = request.get("name").unwrap_or(initial.name());
    let mut argv = vec![name.to_string()];
    argv.extend(flags(request, &FIGURE_FLAGS)?);
    FigureRequest::try_parse_from(argv).map_err(|e| clap_refusal(&e))
}

/// The library's refusal of a request that parsed (a rod too short, a
/// layer the figure does not draw), as the command line words it.
fn refused(e: Error) -> Refusal {
    Refusal::new(422, &crate::cli::flags::said(e).to_string())
}

/// The figure asked for. A mechanism figure is drawn as `animate` draws
/// its frames: in one view held over the whole turn (and its own pose),
/// so that the crank pin stays under the pointer that drags it; a diagram
/// as `figure` draws it.
fn draw(asked: &FigureRequest, options: &FigureOptions) -> Result<Figure> {
    match asked.name.scene_with(options)? {
        Some(scene) => {
            let mut held: Vec<Angle> = (0..360).map(|d| Angle::deg(f64::from(d))).collect();
            held.extend(scene.angles().iter().copied());
            scene.with_held_view(held).figure()
        }
        None => asked.name.figure(options),
    }
}

/// The figure and the values `analyze --json` gives for its pose, as
/// `{"svg", "analyze"}`; values the figure refuses (a refusal of status
/// 422: a rod too short, a layer it does not draw), as `{"refused":
/// reason}` with the status 200. The page asks for a figure at every
/// change of a control, and a value typed halfway is no failure of the
/// page: a 4xx reply would be logged as a failed load in its console. A
/// request that is not a figure request keeps its 4xx status.
fn figure_reply(request: &Request, initial: FigureName) -> std::result::Result<Reply, Refusal> {
    let reply = match figure_json(request, initial) {
        Ok(json) => json,
        Err(refusal) if refusal.status() == 422 => {
            serde_json::json!({ "refused": refusal.reason() })
        }
        Err(refusal) => return Err(refusal),
    };
    Ok(Reply::ok(
        "application/json",
        reply.to_string().into_bytes(),
    ))
}

/// The figure request's reply: the figure's SVG and its values.
fn figure_json(
    request: &Request,
    initial: FigureName,
) -> std::result::Result<serde_json::Value, Refusal> {
    let asked = figure_request(request, initial)?;
    let options = options(&asked.flags, asked.name).map_err(refused)?;
    let figure = draw(&asked, &options).map_err(refused)?;
    let analyze = values(&asked, &options).map_err(refused)?;
    Ok(serde_json::json!({ "svg": to_svg(&figure), "analyze": analyze }))
}

/// The `analyze --json` object of the pose drawn: the scene's of a
/// mechanism figure; for a diagram that follows a pose, the engine and
/// angle asked for (the figure's own where not given); none for others.
fn values(asked: &FigureRequest, options: &FigureOptions) -> Result<Option<serde_json::Value>> {
    let name = asked.name;
    let flags = &asked.flags;
    let units = flags.units.units(name.units());
    if let Some(scene) = name.scene_with(options)? {
        let degrees = scene.angles().first().map_or(0.0, |a| a.degrees());
        let json = super::analyze::json_at(scene.mechanism(), degrees, scene.omega(), &units)?;
        return Ok(Some(json));
    }
    if flags.angle.is_none() || flags.crank.is_none() {
        return Ok(None);
    }
    let m: SliderCrank = options.mechanism.unwrap_or_else(|| name.mechanism());
    let degrees = flags.angle.unwrap_or(name.angle_degrees());
    let omega = options
        .omega
        .unwrap_or_else(|| rpm_to_omega(slider_crank::sources::RPM));
    super::analyze::json_at(&m, degrees, omega, &units).map(Some)
}

/// The figure as a file to save: SVG (its faces embedded), PNG, PDF or
/// TikZ (the picture alone, for a LaTeX book).
fn download_reply(request: &Request, initial: FigureName) -> std::result::Result<Reply, Refusal> {
    let (format, kind, ext) = match request.get("format") {
        Some("svg") => (FileFormat::Svg, "image/svg+xml", "svg"),
        Some("png") => (FileFormat::Png, "image/png", "png"),
        Some("pdf") => (FileFormat::Pdf, "application/pdf", "pdf"),
        Some("tikz") => (FileFormat::Tikz, "application/x-tex", "tex"),
        _ => return Err(Refusal::new(400, "format is svg, png, pdf or tikz")),
    };
    let asked = figure_request(request, initial)?;
    let options = options(&asked.flags, asked.name).map_err(refused)?;
    let figure = draw(&asked, &options).map_err(refused)?;
    let bytes = if format == FileFormat::Svg {
        to_svg_with_fonts(&figure).into_bytes()
    } else {
        format.encode(&figure, &to_svg(&figure)).map_err(refused)?
    };
    let file = format!("{}.{ext}", asked.name.name());
    Ok(Reply::download(kind, bytes, &file))
}

/// The handout of the engine, read as `handout FLAGS`.
fn handout_reply(request: &Request) -> std::result::Result<Reply, Refusal> {
    let argv = flags(request, &HANDOUT_FLAGS)?;
    let asked = HandoutRequest::try_parse_from(argv).map_err(|e| clap_refusal(&e))?;
    let page = template(&asked.args)
        .and_then(|h| h.page())
        .map_err(refused)?;
    Ok(Reply::download(
        "text/html; charset=utf-8",
        page.into_bytes(),
        "handout.html",
    ))
}

/// Answers one request.
fn route(request: &Request, page: &str, initial: FigureName) -> Reply {
    let reply = match request.path() {
        "/" => Ok(Reply::ok(
            "text/html; charset=utf-8",
            page.as_bytes().to_vec(),
        )),
        "/worker.js" => Ok(Reply::ok(
            "text/javascript; charset=utf-8",
            WORKER.as_bytes().to_vec(),
        )),
        "/figure" => figure_reply(request, initial),
        "/download" => download_reply(request, initial),
        "/handout" => handout_reply(request),
        "/favicon.ico" => Ok(Reply::empty()),
        other => Err(Refusal::new(
            404,
            &format!("no page {}", Error::show(other)),
        )),
    };
    reply.unwrap_or_else(|refusal| Reply::refused(&refusal))
}

/// Runs the subcommand: prints the address and serves until Ctrl-C.
pub fn run(args: &ExploreArgs, out: &mut Stdout) -> Result<()> {
    let explorer = Explorer::bind(args.port).map_err(|e| Error::Io {
        message: format!(
            "cannot listen on 127.0.0.1 port {}: {e} (give another --port, or --port 0 for a free one)",
            args.port
        ),
        path: None,
        source: Some(Arc::new(e)),
    })?;
    let port = explorer.port();
    let also = if explorer.addresses().iter().any(|a| a.is_ipv6()) {
        format!(" (also http://[::1]:{port}/)")
    } else {
        String::new()
    };
    out.text(&format!(
        "slider-crank explore: open http://127.0.0.1:{port}/{also}; Ctrl-C ends it\n"
    ))?;
    out.finish()?;
    let initial = args.name;
    let page = page(initial);
    let handler = move |request: &Request| route(request, &page, initial);
    explorer.serve(Arc::new(handler)).map_err(|e| Error::Io {
        message: format!("the explorer stopped: {e}"),
        path: None,
        source: Some(Arc::new(e)),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// A value a hand or a hostile client might give a flag: a number of
    /// any size or none, a name, empty, or any text.
    fn any_value() -> impl Strategy<Value = String> {
        prop_oneof![
            (-1e3f64..1e3).prop_map(|x| x.to_string()),
            prop::num::f64::ANY.prop_map(|x| x.to_string()),
            Just(String::new()),
            "[a-z,-]{1,20}",
            "\\PC{0,12}",
        ]
    }

    /// A query of the names a page sends (and two it never does).
    fn any_query() -> impl Strategy<Value = Vec<(String, String)>> {
        let names = prop::sample::select(vec![
            "name", "crank", "rod", "offset", "angle", "rpm", "omega", "layers", "style", "font",
            "notation", "unit", "mirror", "fit", "mass", "bogus", "data",
        ]);
        prop::collection::vec((names.prop_map(String::from), any_value()), 0..5)
    }

    /// `query` percent-encoded into a request for `/figure`.
    fn request(query: &[(String, String)]) -> Option<Request> {
        let encode = |t: &str| -> String { t.bytes().map(|b| format!("%{b:02X}")).collect() };
        let q: Vec<String> = query
            .iter()
            .map(|(k, v)| format!("{}={}", encode(k), encode(v)))
            .collect();
        let head = format!(
            "GET /figure?{} HTTP/1.1\r\nHost: 127.0.0.1:8744\r\n\r\n",
            q.join("&")
        );
        Request::parse(head.as_bytes(), 8744).ok().flatten()
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(512))]

        // Any query of the page's names, with any values, is answered:
        // 200 with a figure and its values or the reason it is refused,
        // or a 400 of one line for what is not a figure request; never a
        // panic, a 5xx, or NaN in the figure.
        #[test]
        fn any_figure_query_is_drawn_or_refused(query in any_query()) {
            let Some(request) = request(&query) else { return Ok(()) };
            let reply = route(&request, "", FigureName::Fig66Kisch);
            let body = String::from_utf8(reply.body().to_vec()).unwrap();
            match reply.status() {
                200 => {
                    let json: serde_json::Value = serde_json::from_str(&body).unwrap();
                    match (json.get("svg"), json.get("refused")) {
                        (Some(svg), None) => {
                            let svg = svg.as_str().unwrap();
                            prop_assert!(!svg.contains("NaN"), "{query:?}");
                        }
                        (None, Some(r)) => prop_assert!(!r.as_str().unwrap().contains('\n')),
                        _ => prop_assert!(false, "{body}"),
                    }
                }
                400 => prop_assert_eq!(body.lines().count(), 1),
                other => prop_assert!(false, "{other}: {body}"),
            }
        }
    }
}
