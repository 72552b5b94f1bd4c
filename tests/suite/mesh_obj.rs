//! Reading OBJ files (`rigid::mesh::read_obj`): counts, fan triangulation, and refusals
//! that name the file and the line.

use fixstep::math::Fx;
use fixstep::rigid::TriMesh;
use fixstep::rigid::mesh::read_obj;

fn read(text: &str) -> Result<TriMesh<Fx>, String> {
    read_obj::<Fx>(text, "level.obj")
}

fn refused(text: &str, line: usize, what: &str) {
    let e = read(text).expect_err("refused");
    let start = format!("level.obj: line {line}: ");
    assert!(e.starts_with(&start), "{e:?} does not start with {start:?}");
    assert!(e.contains(what), "{what:?} not in {e:?}");
}

const QUAD: &str = "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1 2 3 4\n";

#[test]
fn a_quad_is_two_triangles() {
    let mesh = read(QUAD).expect("reads");
    assert_eq!(mesh.vertices().len(), 4);
    assert_eq!(mesh.triangles(), &[[0, 1, 2], [0, 2, 3]]);
}

#[test]
fn a_cube_in_two_groups_is_one_mesh() {
    let cube = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
                o a\nf 1 4 3 2\nf 5 6 7 8\ng b\nf 1 2 6 5\nf 2 3 7 6\nusemtl x\n\
                f 3/1/1 4/1/1 8/1/1 7/1/1\nf -8 -4 -1 -5\n";
    let mesh = read(cube).expect("reads");
    assert_eq!(mesh.vertices().len(), 8);
    assert_eq!(mesh.triangles().len(), 12);
}

#[test]
fn a_polygon_is_a_fan() {
    let text = "v 0 0 0\nv 2 0 0\nv 3 0 1\nv 2 0 2\nv 0 0 2\nf 1 2 3 4 5\n";
    let mesh = read(text).expect("reads");
    assert_eq!(mesh.triangles(), &[[0, 1, 2], [0, 2, 3], [0, 3, 4]]);
}

#[test]
fn bad_files_name_the_line() {
    assert!(read("").unwrap_err().contains("no triangles"));
    assert!(
        read("v 0 0 0\n")
            .unwrap_err()
            .starts_with("level.obj: no triangles")
    );
    refused("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n", 4, "degenerate");
    refused(
        "v 0 0 0\nv 1 0 0\nv 1 0 1\nf 1 2 4\n",
        4,
        "index 4 is out of range",
    );
    refused("v 0 0 0\nv 1 0 0\nv 1 0 1\nf 0 1 2\n", 4, "index 0");
    refused(
        "v 0 0 0\nv 1 0 0\nv 1 0 1\nf -4 -1 -2\n",
        4,
        "index -4 is out of range",
    );
    refused(
        "v 0 0 0\nv nan 0 0\nv 1 0 1\nf 1 2 3\n",
        2,
        "not a finite number",
    );
    refused(
        "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 1e6 0 0\nf 1 2 4\n",
        4,
        "beyond",
    );
    refused("v 0 0 0\nv 1 x 0\nv 1 0 1\nf 1 2 3\n", 2, "cannot read");
    refused(
        "v 0 0 0\nv 1 0 0\nv 1 0 1\nf 1 2\n",
        4,
        "at least 3 corners",
    );
    let fan = "v 0 0 0\nv 1 0 0\nv 0 0 1\nv 0 1 0\nv 0 -1 0\n\
               f 1 2 3\nf 2 1 4\nf 1 2 5\n";
    refused(fan, 8, "non-manifold");
}
