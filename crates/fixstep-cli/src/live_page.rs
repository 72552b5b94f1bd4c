//! `fixstep render INPUT --html PAGE.html`: the live 3D player of `web/` (the page
//! `scripts/web.sh` serves) as one page that plays INPUT in WebAssembly. The page is
//! `web/index.html` with a `<base>` at the live page's address (`--web`), from which it
//! loads its scripts, three.js and the wasm package, and the replay's bytes in base64: a
//! replay file's own bytes, or a scene's run recorded as `fixstep run --record` records it.

use std::path::Path;

use super::args::RenderArgs;
use super::file_identity::{NamedFile, refuse_shared_files};
use super::output::print_line;
use super::output_file::OutputFile;
use super::scene_arg::{resolve_scene, scene_file};
use super::status::Status;
use fixstep::replay::{DEFAULT_CHECKSUM_EVERY, Replay, record};
use fixstep::world::checksum::hex;

/// The live page, whose `<base>` and embedded replay this command adds.
const LIVE_PAGE: &str = include_str!("../../../web/index.html");

/// Where `scripts/web.sh` serves the live page.
pub const DEFAULT_WEB: &str = "http://127.0.0.1:8000/";

/// The line of the live page after which the `<base>` and the replay go (the `<meta>`
/// naming the charset stays first).
const ANCHOR: &str = "<meta charset=\"utf-8\">\n";

/// Refuses a page that would overwrite the replay it embeds.
pub fn refuse_clashes(args: &RenderArgs) -> Result<(), String> {
    let Some(page) = &args.html else {
        return Ok(());
    };
    let mut inputs = Vec::new();
    if let Some(path) = scene_file(&args.input) {
        inputs.push(NamedFile::new("the input", path));
    }
    refuse_shared_files(&inputs, &[NamedFile::new("--html", page)])
}

/// Writes the page (to a temporary file renamed into place). Prints what it wrote and,
/// last, `checksum: <16 hex digits>`, the replay's final checksum, which the page shows
/// when it has played it.
pub fn write_live_page(args: &RenderArgs) -> Result<Status, String> {
    let page = args.html.as_deref().expect("called with --html");
    check_page_name(page)?;
    let web = args.web.as_deref().unwrap_or(DEFAULT_WEB);
    check_web(web)?;
    let (name, bytes) = replay_bytes(&args.input, args.ticks)?;
    let replay = Replay::from_bytes(&bytes, &name).map_err(|e| e.to_string())?;
    let html = live_page(web, &name, &bytes)?;
    OutputFile::write(page, html.as_bytes())?;
    print_line(&format!(
        "{}: {} ticks, live page {} (its player from {web}: serve it with ./scripts/web.sh)",
        replay.scene().name,
        replay.ticks(),
        page.display()
    ))?;
    print_line(&format!("checksum: {}", hex(replay.final_checksum())))?;
    Ok(Status::Ok)
}

/// The replay file's name and bytes: a replay file as it is (its first `ticks` ticks,
/// recorded again, when `ticks` is fewer than it holds), or the scene `input` run with its
/// script for `ticks` (default: the scene's) and recorded.
fn replay_bytes(input: &str, ticks: Option<u64>) -> Result<(String, Vec<u8>), String> {
    let file_name = |path: &str| {
        Path::new(path)
            .file_name()
            .map_or_else(|| path.to_owned(), |n| n.to_string_lossy().into_owned())
    };
    if input.ends_with(".replay") {
        let bytes = std::fs::read(input).map_err(|e| format!("{input}: cannot read: {e}"))?;
        let replay = Replay::from_bytes(&bytes, input).map_err(|e| e.to_string())?;
        return match ticks {
            Some(ticks) if ticks < replay.ticks() => {
                let mut scene = replay.scene().clone();
                scene.script = replay.inputs().to_vec();
                Ok((file_name(input), record_bytes(input, &scene, ticks)?))
            }
            _ => Ok((file_name(input), bytes)),
        };
    }
    let scene = resolve_scene(input)?;
    let ticks = ticks.unwrap_or(scene.ticks);
    let name = format!("{}.replay", scene.name);
    Ok((name, record_bytes(input, &scene, ticks)?))
}

/// `scene` run with its script for `ticks` ticks, as replay bytes.
fn record_bytes(
    input: &str,
    scene: &fixstep::scene::Scene<fixstep::math::Fx>,
    ticks: u64,
) -> Result<Vec<u8>, String> {
    record(scene, ticks, DEFAULT_CHECKSUM_EVERY)
        .map_err(|e| format!("{input}: {e}"))?
        .to_bytes()
        .map_err(|e| format!("{input}: cannot encode the replay: {e}"))
}

/// The live page with its `<base>` at `web` and the replay `name` (`bytes`) embedded.
fn live_page(web: &str, name: &str, bytes: &[u8]) -> Result<String, String> {
    let at = LIVE_PAGE
        .find(ANCHOR)
        .map(|i| i + ANCHOR.len())
        .ok_or("web/index.html has no <meta charset> line (a build of a changed page)")?;
    // The name goes inside a script as a JSON string: no `<`, quote or backslash can end it.
    let name: String = name
        .chars()
        .map(|c| match c {
            '<' | '>' | '"' | '\\' | '&' => '_',
            c if c.is_control() => '_',
            c => c,
        })
        .collect();
    Ok(format!(
        "{}<base href=\"{web}\">\n<script>window.fixstepReplay = {{ name: \"{name}\", base64: \
         \"{}\" }};</script>\n{}",
        &LIVE_PAGE[..at],
        base64(bytes),
        &LIVE_PAGE[at..]
    ))
}

/// A page's name must end in `.html` (so that a mistyped option never overwrites another
/// kind of file).
fn check_page_name(page: &Path) -> Result<(), String> {
    if page.extension().is_some_and(|e| e == "html") && !page.is_dir() {
        Ok(())
    } else {
        Err(format!(
            "--html: `{}`: the page's name must end in .html",
            page.display()
        ))
    }
}

/// The live page's address: `http://` or `https://` (or a relative path), ending in `/`,
/// with nothing that would end the attribute it goes in.
fn check_web(web: &str) -> Result<(), String> {
    let bad = web
        .chars()
        .find(|c| c.is_whitespace() || c.is_control() || matches!(c, '"' | '<' | '>' | '\''));
    if let Some(c) = bad {
        return Err(format!("--web: `{web}`: {c:?} cannot be in the address"));
    }
    if !web.ends_with('/') {
        return Err(format!(
            "--web: `{web}`: the address of the live page's folder must end in `/` (such as \
             {DEFAULT_WEB})"
        ));
    }
    if web.contains("://") && !(web.starts_with("http://") || web.starts_with("https://")) {
        return Err(format!(
            "--web: `{web}`: only http:// and https:// addresses"
        ));
    }
    Ok(())
}

/// Standard base64 (RFC 4648, with `=` padding).
fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            chunk.get(1).copied().unwrap_or(0),
            chunk.get(2).copied().unwrap_or(0),
        ];
        let n = u32::from(b[0]) << 16 | u32::from(b[1]) << 8 | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(char::from(ALPHABET[(n >> (18 - 6 * k) & 63) as usize]));
            } else {
                out.push('=');
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_is_rfc_4648_s() {
        // RFC 4648, section 10.
        for (text, expected) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(text.as_bytes()), expected);
        }
    }

    #[test]
    fn the_page_keeps_the_charset_first_and_escapes_the_name() {
        let page = live_page(DEFAULT_WEB, "a\"</script>.replay", b"xyz").expect("a page");
        assert!(page.starts_with("<!doctype html>"));
        let base = page
            .find("<base href=\"http://127.0.0.1:8000/\">")
            .expect("base");
        assert!(page.find(ANCHOR).expect("charset") < base);
        assert!(page.contains("name: \"a__/script_.replay\", base64: \"eHl6\""));
        assert!(page.contains("<script type=\"module\" src=\"./main.js\"></script>"));
    }
}
