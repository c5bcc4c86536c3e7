//! Shows a fuzz input: what it decodes to (WKT), what the target's check says, and with a third
//! argument, its picture as SVG. `cargo run -p clip-fuzz-checks --example show -- vatti FILE [OUT.svg]`

use clip_fuzz_checks::picture::picture;
use clip_fuzz_checks::{lines, target, vatti, windows};
use clip_testkit::case_record::{polygons_to_wkt, segments_to_wkt};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [name, file, rest @ ..] = args.as_slice() else {
        eprintln!("usage: show TARGET FILE [OUT.svg]");
        std::process::exit(2);
    };
    let Some(t) = target(name) else {
        eprintln!("unknown target {name}");
        std::process::exit(2);
    };
    let data = std::fs::read(file).expect("readable input");
    match name.as_str() {
        "vatti" => {
            if let Some(c) = vatti::decode(&data) {
                println!(
                    "fill {}\nsubject {}\nclip {}",
                    c.fill,
                    polygons_to_wkt(&c.subject, false),
                    polygons_to_wkt(&c.clip, false)
                );
            }
        }
        "window_clippers" => {
            if let Some(c) = windows::decode(&data) {
                println!(
                    "fill {}\nsubject {}\nwindow {}",
                    c.fill,
                    polygons_to_wkt(&c.subject, false),
                    polygons_to_wkt(&c.window, false)
                );
            }
        }
        "line_clippers" => {
            if let Some(c) = lines::decode(&data) {
                println!("window {}\nsegments {}", polygons_to_wkt(&c.window, false), segments_to_wkt(&c.segments));
            }
        }
        _ => println!("{}", String::from_utf8_lossy(&data)),
    }
    match (t.check)(&data) {
        Ok(()) => println!("check: passes"),
        Err(why) => println!("check: FAILS: {why}"),
    }
    if let [out, ..] = rest {
        let svg = picture(name, &data).expect("a geometric target");
        std::fs::write(out, svg).expect("writable picture");
    }
}
