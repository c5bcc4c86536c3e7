//! The binary speaks the protocol: a handshake first, then one reply per request line.

use std::io::{BufRead, BufReader, Write};
use std::process::{Command, Stdio};

#[test]
fn handshake_then_replies_with_the_request_ids() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_clipbench-rust-example"))
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .expect("the example starts");
    let mut stdin = child.stdin.take().unwrap();
    let mut lines = BufReader::new(child.stdout.take().unwrap()).lines();
    let handshake: serde_json::Value = serde_json::from_str(&lines.next().unwrap().unwrap()).unwrap();
    assert_eq!(handshake["protocol"], 1);
    assert_eq!(handshake["polygon"]["fill_rules"], serde_json::json!(["even-odd"]));
    let request = r#"{"id":41,"op":"intersection","fill":"even-odd","subject":[[[0,0],[2,0],[2,2],[0,2]]],"clip":[[[1,1],[3,1],[3,3],[1,3]]]}"#;
    writeln!(stdin, "{request}").unwrap();
    let reply: serde_json::Value = serde_json::from_str(&lines.next().unwrap().unwrap()).unwrap();
    assert_eq!(reply["id"], 41);
    assert_eq!(reply["rings"].as_array().unwrap().len(), 1);
    assert!(reply["time_ns"].as_u64().is_some());
    drop(stdin);
    assert!(child.wait().unwrap().success(), "it exits at the end of its input");
}
