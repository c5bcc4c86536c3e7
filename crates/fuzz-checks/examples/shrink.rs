//! Shrinks a failing `vatti` fuzz input while its check still fails with a message containing
//! `NEEDLE`, prints the smaller case as WKT and writes its bytes to `OUT`.
//! `cargo run -p clip-fuzz-checks --example shrink -- FILE NEEDLE OUT`

use clip_fuzz_checks::{encode, vatti};
use clip_testkit::case_record::polygons_to_wkt;
use clip_testkit::shrink::shrink_polygons;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [file, needle, out] = args.as_slice() else {
        eprintln!("usage: shrink FILE NEEDLE OUT");
        std::process::exit(2);
    };
    let data = std::fs::read(file).expect("readable input");
    let Some(case) = vatti::decode(&data) else {
        eprintln!("{file}: too short to decode");
        std::process::exit(2);
    };
    let fails = |c: &vatti::VattiCase| vatti::check(c).err().filter(|why| why.contains(needle.as_str()));
    if fails(&case).is_none() {
        eprintln!("{file}: the check does not fail with {needle:?}");
        std::process::exit(1);
    }
    let fill = case.fill;
    let (subject, clip) = shrink_polygons(&case.subject, &case.clip, |s, c| {
        fails(&vatti::VattiCase { subject: s.clone(), clip: c.clone(), fill }).map(|_| ())
    });
    let small = vatti::VattiCase { subject, clip, fill };
    let bytes = encode::vatti(&small.subject, &small.clip, fill);
    // The encoding must decode to the same case, or the bytes would not replay it.
    assert_eq!(vatti::decode(&bytes).as_ref(), Some(&small), "the encoding round-trips");
    std::fs::write(out, &bytes).expect("writable output");
    println!(
        "fill {fill}\nsubject {}\nclip {}\nfails: {}",
        polygons_to_wkt(&small.subject, false),
        polygons_to_wkt(&small.clip, false),
        fails(&small).unwrap_or_default()
    );
}
