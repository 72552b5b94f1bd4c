//! `fixstep render INPUT --html PAGE.html`: the live 3D player as one page holding the
//! replay it plays (a replay file's own bytes, or a scene's run recorded), written whole or
//! not at all; bad arguments exit 2 with one line.

use crate::replay_support::{TempPath, fixstep, names_in};
use fixstep::replay::Replay;

/// The replay embedded in a written page, decoded from its base64.
fn embedded(page: &str) -> Vec<u8> {
    let start = page.find("base64: \"").expect("an embedded replay") + 9;
    let end = start + page[start..].find('"').expect("its end");
    decode_base64(&page[start..end])
}

/// Standard base64 with padding.
fn decode_base64(text: &str) -> Vec<u8> {
    let value = |c: u8| match c {
        b'A'..=b'Z' => c - b'A',
        b'a'..=b'z' => c - b'a' + 26,
        b'0'..=b'9' => c - b'0' + 52,
        b'+' => 62,
        b'/' => 63,
        _ => panic!("not base64: {c}"),
    };
    let mut out = Vec::new();
    for chunk in text.as_bytes().chunks(4) {
        let data: Vec<u8> = chunk
            .iter()
            .filter(|&&c| c != b'=')
            .map(|&c| value(c))
            .collect();
        let n = data
            .iter()
            .enumerate()
            .fold(0u32, |n, (k, &v)| n | u32::from(v) << (18 - 6 * k));
        out.extend(n.to_be_bytes()[1..data.len()].iter());
    }
    out
}

#[test]
fn a_replay_s_page_embeds_its_bytes_and_points_at_the_live_page() {
    let replay = format!("{}/../../replays/stack.replay", env!("CARGO_MANIFEST_DIR"));
    let dir = TempPath::new("live");
    std::fs::create_dir(dir.path()).expect("a folder");
    let page = dir.path().join("stack.html");
    let run = fixstep(&["render", &replay, "--html", page.to_str().expect("UTF-8")]);
    assert_eq!(run.code, 0, "{run:?}");
    let bytes = std::fs::read(&replay).expect("the replay");
    let checksum = Replay::from_bytes(&bytes, "stack")
        .expect("decodes")
        .final_checksum();
    assert!(
        run.stdout
            .ends_with(&format!("checksum: {checksum:016x}\n")),
        "{}",
        run.stdout
    );
    let html = std::fs::read_to_string(&page).expect("the page");
    assert_eq!(embedded(&html), bytes, "the replay's own bytes");
    assert!(html.contains("<base href=\"http://127.0.0.1:8000/\">"));
    assert!(html.contains("name: \"stack.replay\""));
    assert!(html.contains("id=\"checksum\""), "the live page's elements");
    assert_eq!(
        names_in(dir.path()),
        ["stack.html"],
        "no temporary file left"
    );
}

#[test]
fn a_scene_s_page_holds_its_run_recorded_for_the_ticks_asked() {
    let page = TempPath::new("pyramid.html");
    let run = fixstep(&[
        "render",
        "pyramid",
        "--ticks",
        "30",
        "--html",
        page.str(),
        "--web",
        "https://example.org/fixstep/",
    ]);
    assert_eq!(run.code, 0, "{run:?}");
    let native = fixstep(&["run", "pyramid", "--ticks", "30"]);
    let last = native.stdout.lines().last().expect("a checksum line");
    assert!(
        run.stdout.ends_with(&format!("{last}\n")),
        "{run:?} vs {last}"
    );
    let html = std::fs::read_to_string(page.path()).expect("the page");
    let replay = Replay::from_bytes(&embedded(&html), "page").expect("a replay");
    assert_eq!(replay.ticks(), 30);
    assert_eq!(replay.scene().name, "pyramid");
    assert!(html.contains("<base href=\"https://example.org/fixstep/\">"));
}

#[test]
fn bad_arguments_exit_2_and_write_nothing() {
    let page = TempPath::new("page.html");
    let not_html = TempPath::new("page.png");
    for (args, parts) in [
        (
            vec!["--html", not_html.str()],
            vec!["--html", "must end in .html"],
        ),
        (
            vec!["--html", page.str(), "--web", "http://127.0.0.1:8000"],
            vec!["--web", "must end in `/`"],
        ),
        (
            vec!["--html", page.str(), "--web", "ftp://host/"],
            vec!["--web", "only http:// and https://"],
        ),
        (
            vec!["--html", page.str(), "--web", "http://a/\"x/"],
            vec!["--web", "cannot be in the address"],
        ),
        (vec!["--html", page.str(), "--every", "2"], vec!["--every"]),
        (vec!["--web", "http://a/"], vec!["--html"]),
    ] {
        let mut line = vec!["render", "stack"];
        line.extend(args);
        fixstep(&line).assert_error(&parts);
    }
    fixstep(&["render", "nope", "--html", page.str()]).assert_error(&["nope"]);
    let cut = TempPath::with_bytes("cut.replay", b"FXRPnot really");
    fixstep(&["render", cut.str(), "--html", page.str()]).assert_error(&["cut.replay"]);
    assert!(!page.path().exists() && !not_html.path().exists());
}
