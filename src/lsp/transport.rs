//! The language server's stdio transport (LANGUAGE.md §15): JSON-RPC
//! messages framed by a `Content-Length` header, read on one thread and
//! written on another, as `lsp-server`'s own stdio transport does, with one
//! difference: a message whose body is not a JSON-RPC message does not end
//! the connection. Its length is known from its header, so the reader
//! answers it as JSON-RPC 2.0 says (§5.1: a parse error, −32700, or an
//! invalid request, −32600, with the request's id when it has one, else
//! null) and reads on. Only a header that cannot be read, which leaves no
//! way to find where the next message starts, ends the connection, with
//! the reason.

use std::io::{self, BufRead, Write};
use std::thread;

use crossbeam_channel::{Receiver, Sender, bounded, select, unbounded};
use lsp_server::{Connection, Message};

/// The threads that move messages between stdio and a [`Connection`].
pub struct Transport {
    reader: thread::JoinHandle<io::Result<()>>,
    writer: thread::JoinHandle<io::Result<()>>,
}

impl Transport {
    /// Waits for both threads; the reader's error (a header that cannot be
    /// read, stdin failing) first, then the writer's.
    pub fn join(self) -> io::Result<()> {
        let read = self
            .reader
            .join()
            .unwrap_or_else(|_| Err(io::Error::other("reader panicked")));
        let written = self
            .writer
            .join()
            .unwrap_or_else(|_| Err(io::Error::other("writer panicked")));
        read.and(written)
    }
}

/// A connection over stdin and stdout, and the threads that serve it.
pub fn stdio() -> (Connection, Transport) {
    let (to_server, from_client) = bounded::<Message>(0);
    let (to_client, outgoing) = bounded::<Message>(0);
    // (unbounded: the reader never waits on a writer that has ended)
    let (answer, answers) = unbounded::<String>();
    let writer = thread::Builder::new()
        .name("chasles-lsp-writer".into())
        .spawn(move || write_all(&mut io::stdout().lock(), &outgoing, &answers))
        .expect("the writer thread starts");
    let reader = thread::Builder::new()
        .name("chasles-lsp-reader".into())
        .spawn(move || read_all(&mut io::stdin().lock(), &to_server, &answer))
        .expect("the reader thread starts");
    let conn = Connection {
        sender: to_client,
        receiver: from_client,
    };
    (conn, Transport { reader, writer })
}

/// Writes the server's messages and the reader's answers to `out` until the
/// server lets go of its sender (its answers after that are dropped: the
/// server has ended).
fn write_all(
    out: &mut impl Write,
    outgoing: &Receiver<Message>,
    answers: &Receiver<String>,
) -> io::Result<()> {
    loop {
        select! {
            recv(outgoing) -> m => match m {
                Ok(m) => m.write(out)?,
                Err(_) => return Ok(()),
            },
            recv(answers) -> a => if let Ok(a) = a {
                write!(out, "Content-Length: {}\r\n\r\n{a}", a.len())?;
                out.flush()?;
            },
        }
    }
}

/// Reads messages from `input` and sends them to the server until the end
/// of input, the client's `exit`, or the server's end; answers a body that
/// is not a message (see the module's comment) through `answer`.
pub fn read_all(
    input: &mut impl BufRead,
    to_server: &Sender<Message>,
    answer: &Sender<String>,
) -> io::Result<()> {
    while let Some(body) = read_body(input)? {
        let msg = match message(&body) {
            Ok(m) => m,
            Err(reply) => {
                // (the writer may be gone with the server: nothing to tell)
                let _ = answer.send(reply);
                continue;
            }
        };
        let exit = matches!(&msg, Message::Notification(n) if n.method == "exit");
        if to_server.send(msg).is_err() {
            return Ok(());
        }
        if exit {
            break;
        }
    }
    Ok(())
}

/// The body of the next message: None at the end of input; an error when
/// its header cannot be read (no `Content-Length`, a line not ended by
/// CRLF, a length that is not a number, input ending inside the body).
fn read_body(input: &mut impl BufRead) -> io::Result<Option<Vec<u8>>> {
    let bad = |what: String| io::Error::new(io::ErrorKind::InvalidData, what);
    let mut size = None;
    let mut line = String::new();
    loop {
        line.clear();
        if input.read_line(&mut line)? == 0 {
            return match size {
                None => Ok(None),
                Some(_) => Err(bad("the input ended inside a header".into())),
            };
        }
        let Some(header) = line.strip_suffix("\r\n") else {
            return Err(bad(format!("malformed header: {line:?}")));
        };
        if header.is_empty() {
            break;
        }
        let Some((name, value)) = header.split_once(':') else {
            return Err(bad(format!("malformed header: {header:?}")));
        };
        if name.trim().eq_ignore_ascii_case("Content-Length") {
            let n = value.trim().parse::<usize>();
            size = Some(n.map_err(|e| bad(format!("Content-Length {value:?}: {e}")))?);
        }
    }
    let size = size.ok_or_else(|| bad("a message with no Content-Length".into()))?;
    let mut body = vec![0; size];
    input.read_exact(&mut body)?;
    Ok(Some(body))
}

/// The message a body holds, or the JSON-RPC error response to send back
/// for it: a parse error (−32700) when it is not JSON, an invalid request
/// (−32600) when it is JSON but no request, response or notification.
fn message(body: &[u8]) -> Result<Message, String> {
    let reply = |id: serde_json::Value, code: i32, what: String| {
        serde_json::json!({
            "jsonrpc": "2.0",
            "id": id,
            "error": {"code": code, "message": what},
        })
        .to_string()
    };
    let json: serde_json::Value = serde_json::from_slice(body)
        .map_err(|e| reply(serde_json::Value::Null, -32700, format!("not JSON: {e}")))?;
    let id = match json.get("id") {
        Some(id @ (serde_json::Value::Number(_) | serde_json::Value::String(_))) => id.clone(),
        _ => serde_json::Value::Null,
    };
    serde_json::from_value(json).map_err(|e| {
        reply(
            id,
            -32600,
            format!("not a JSON-RPC request, response or notification: {e}"),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame(body: &str) -> String {
        format!("Content-Length: {}\r\n\r\n{body}", body.len())
    }

    /// Reads `input` to its end: the messages the server gets, and the
    /// answers the reader gives.
    fn read(input: &str) -> (Vec<Message>, Vec<serde_json::Value>, io::Result<()>) {
        let (to_server, got) = crossbeam_channel::unbounded();
        let (answer, answers) = crossbeam_channel::unbounded();
        let r = read_all(&mut input.as_bytes(), &to_server, &answer);
        let answers = answers
            .try_iter()
            .map(|a| serde_json::from_str(&a).unwrap())
            .collect();
        (got.try_iter().collect(), answers, r)
    }

    #[test]
    fn a_body_that_is_not_json_is_answered_and_reading_goes_on() {
        let ok = r#"{"jsonrpc":"2.0","id":2,"method":"shutdown"}"#;
        let (got, answers, r) = read(&(frame("hello") + &frame(ok)));
        r.unwrap();
        assert_eq!(answers.len(), 1);
        assert_eq!(answers[0]["error"]["code"], -32700);
        assert_eq!(answers[0]["id"], serde_json::Value::Null);
        assert!(matches!(&got[..], [Message::Request(q)] if q.method == "shutdown"));
    }

    #[test]
    fn json_that_is_no_message_is_an_invalid_request_with_its_id() {
        let (got, answers, r) = read(&(frame(r#"{"id": 7, "params": 1}"#) + &frame("[1, 2]")));
        r.unwrap();
        assert!(got.is_empty());
        assert_eq!(answers[0]["error"]["code"], -32600);
        assert_eq!(answers[0]["id"], 7);
        assert_eq!(answers[1]["error"]["code"], -32600);
        assert_eq!(answers[1]["id"], serde_json::Value::Null);
    }

    #[test]
    fn a_header_that_cannot_be_read_ends_reading_with_the_reason() {
        for bad in [
            "Content-Length: 5\nhello",
            "Content-Type: x\r\n\r\n{}",
            "Content-Length: five\r\n\r\n",
        ] {
            let (got, _, r) = read(bad);
            assert!(got.is_empty());
            let e = r.unwrap_err();
            assert_eq!(e.kind(), io::ErrorKind::InvalidData, "{bad:?}: {e}");
        }
        // input ending inside a body
        let (_, _, r) = read("Content-Length: 50\r\n\r\n{}");
        assert_eq!(r.unwrap_err().kind(), io::ErrorKind::UnexpectedEof);
    }

    #[test]
    fn reading_stops_after_exit() {
        let exit = r#"{"jsonrpc":"2.0","method":"exit"}"#;
        let after = r#"{"jsonrpc":"2.0","id":3,"method":"shutdown"}"#;
        let (got, _, r) = read(&(frame(exit) + &frame(after)));
        r.unwrap();
        assert_eq!(got.len(), 1);
    }
}
