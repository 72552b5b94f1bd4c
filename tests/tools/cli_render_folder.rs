//! `fixstep render` replaces its output folder whole: a render into an earlier render's
//! folder holds only the new frames, and a folder holding anything else is refused.

use crate::replay_support::{TempPath, fixstep, names_in};

/// Renders `scene` for `ticks` ticks, a frame every `every`, into `out`; checks success.
fn render(scene: &str, ticks: &str, every: &str, out: &TempPath) {
    let run = fixstep(&[
        "render",
        scene,
        "--ticks",
        ticks,
        "--every",
        every,
        "--size",
        "32x24",
        "--out",
        out.str(),
    ]);
    assert_eq!(run.code, 0, "{run:?}");
}

#[test]
fn a_render_into_an_earlier_renders_folder_holds_only_its_own_frames() {
    let out = TempPath::new("render-again");
    render("stack", "20", "5", &out);
    assert_eq!(
        names_in(out.path()).len(),
        7,
        "5 frames, the GIF and the page"
    );
    render("cradle", "6", "3", &out);
    assert_eq!(
        names_in(out.path()),
        [
            "animation.gif",
            "index.html",
            "tick-000000.png",
            "tick-000003.png",
            "tick-000006.png"
        ]
    );
    let page = std::fs::read_to_string(out.path().join("index.html")).expect("the page");
    assert!(page.contains("cradle"), "the new render's page");
    let parent = out.path().parent().expect("a parent");
    let prefix = format!(
        ".{}",
        out.path().file_name().expect("a name").to_string_lossy()
    );
    assert!(
        !names_in(parent).iter().any(|n| n.starts_with(&prefix)),
        "no temporary folder left beside it"
    );
}

#[test]
fn a_folder_with_other_files_is_refused_and_kept() {
    let out = TempPath::new("render-foreign");
    std::fs::create_dir(out.path()).expect("create the folder");
    std::fs::write(out.path().join("notes.txt"), b"mine").expect("write");
    std::fs::write(out.path().join("tick-000000.png"), b"not mine either").expect("write");
    let run = fixstep(&["render", "stack", "--ticks", "2", "--out", out.str()]);
    run.assert_error(&["notes.txt", "not a render's file"]);
    assert_eq!(names_in(out.path()), ["notes.txt", "tick-000000.png"]);
    assert_eq!(
        std::fs::read(out.path().join("notes.txt")).expect("kept"),
        b"mine"
    );
}

#[test]
fn a_scene_inside_the_output_folder_is_refused() {
    let out = TempPath::new("render-input-inside");
    std::fs::create_dir(out.path()).expect("create the folder");
    let scene = out.path().join("mine.ron");
    std::fs::write(&scene, b"(name: \"mine\")").expect("write");
    let scene = scene.to_str().expect("UTF-8");
    let run = fixstep(&["render", scene, "--ticks", "2", "--out", out.str()]);
    run.assert_error(&["mine.ron", "not a render's file"]);
    assert_eq!(names_in(out.path()), ["mine.ron"]);
}
