//! `chasles lsp`: the language server (LANGUAGE.md §15), the book's frame
//! checking (§6) in the editor as one types, over stdio on `lsp-server` and
//! `lsp-types` (the pair rust-analyzer is built on).
//!
//! Each open document is re-checked in full in [`Mode::Check`]
//! ([`analysis`]: no numbers, no file written, under a deadline) when it
//! opens and, debounced, after the client's incremental changes pause for
//! [`DEBOUNCE`]; a request on a changed document checks it first. The
//! answers ([`features`]) read the last check: diagnostics with their help,
//! hover, completion, go to definition and document symbols.
//!
//! [`Mode::Check`]: crate::eval::env::Mode::Check

pub mod analysis;
pub mod features;
pub mod text;
pub mod transport;

use std::collections::HashMap;
use std::time::{Duration, Instant};

use crossbeam_channel::RecvTimeoutError;
use lsp_server::{Connection, ErrorCode, Message, Notification, Request, Response};
use lsp_types::notification::{
    DidChangeTextDocument, DidCloseTextDocument, DidOpenTextDocument, Notification as _,
    PublishDiagnostics,
};
use lsp_types::request::{
    Completion, DocumentSymbolRequest, GotoDefinition, HoverRequest, Request as _,
};
use lsp_types::{
    CompletionOptions, CompletionResponse, DocumentSymbolResponse, GotoDefinitionResponse,
    InitializeParams, OneOf, PositionEncodingKind, PublishDiagnosticsParams, ServerCapabilities,
    ServerInfo, TextDocumentPositionParams, TextDocumentSyncCapability, TextDocumentSyncKind, Uri,
};

use crate::session::Settings;
use analysis::Analysis;
use text::{Document, Encoding};

/// How long the text must stay unchanged before a changed document is
/// re-checked and its diagnostics published.
pub const DEBOUNCE: Duration = Duration::from_millis(120);

/// An open document and its last check (none while changes are pending).
struct Open {
    doc: Document,
    analysis: Option<Analysis>,
    /// When a change pending a check may be checked.
    due: Option<Instant>,
}

/// The server's state between messages.
struct Server<'a> {
    conn: &'a Connection,
    settings: Settings,
    enc: Encoding,
    docs: HashMap<Uri, Open>,
}

/// Serves the protocol on stdin and stdout until the client's `exit`;
/// returns the exit code (0 after `shutdown`, 1 otherwise, 2 when the
/// handshake fails).
pub fn serve(settings: Settings) -> i32 {
    let (conn, io) = transport::stdio();
    let code = serve_on(&conn, settings);
    drop(conn);
    // (a header that cannot be read ends the connection: the editor is
    // told why on stderr, its server log, not left with a bare exit)
    match io.join() {
        Ok(()) => code,
        Err(e) => {
            eprintln!("chasles lsp: the connection ended: {e}");
            code.max(1)
        }
    }
}

/// Serves the protocol on `conn` (stdio, or an in-memory pair in tests).
pub fn serve_on(conn: &Connection, settings: Settings) -> i32 {
    let (id, params) = match conn.initialize_start() {
        Ok(x) => x,
        Err(e) => {
            eprintln!("chasles lsp: no initialize request: {e}");
            return 2;
        }
    };
    let params: InitializeParams = serde_json::from_value(params).unwrap_or_default();
    let utf8 = params
        .capabilities
        .general
        .and_then(|g| g.position_encodings)
        .is_some_and(|e| e.contains(&PositionEncodingKind::UTF8));
    let enc = if utf8 {
        Encoding::Utf8
    } else {
        Encoding::Utf16
    };
    let caps = ServerCapabilities {
        position_encoding: Some(if utf8 {
            PositionEncodingKind::UTF8
        } else {
            PositionEncodingKind::UTF16
        }),
        text_document_sync: Some(TextDocumentSyncCapability::Kind(
            TextDocumentSyncKind::INCREMENTAL,
        )),
        hover_provider: Some(lsp_types::HoverProviderCapability::Simple(true)),
        completion_provider: Some(CompletionOptions {
            trigger_characters: Some(vec![":".into(), "*".into()]),
            ..Default::default()
        }),
        definition_provider: Some(OneOf::Left(true)),
        document_symbol_provider: Some(OneOf::Left(true)),
        ..Default::default()
    };
    let result = serde_json::json!({
        "capabilities": caps,
        "serverInfo": ServerInfo {
            name: "chasles".into(),
            version: Some(env!("CARGO_PKG_VERSION").into()),
        },
    });
    if let Err(e) = conn.initialize_finish(id, result) {
        eprintln!("chasles lsp: initialize failed: {e}");
        return 2;
    }
    let mut server = Server {
        conn,
        settings: Settings {
            json: false,
            ..settings
        },
        enc,
        docs: HashMap::new(),
    };
    server.run()
}

impl Server<'_> {
    fn run(&mut self) -> i32 {
        let mut shut_down = false;
        loop {
            let due = self.docs.values().filter_map(|o| o.due).min();
            let msg = match due {
                None => match self.conn.receiver.recv() {
                    Ok(m) => m,
                    Err(_) => return 1,
                },
                Some(at) => {
                    match self
                        .conn
                        .receiver
                        .recv_timeout(at.saturating_duration_since(Instant::now()))
                    {
                        Ok(m) => m,
                        Err(RecvTimeoutError::Timeout) => {
                            self.check_due();
                            continue;
                        }
                        Err(RecvTimeoutError::Disconnected) => return 1,
                    }
                }
            };
            match msg {
                Message::Request(req) => {
                    if shut_down {
                        self.reply_err(req, ErrorCode::InvalidRequest, "the server is shut down");
                        continue;
                    }
                    if req.method == "shutdown" {
                        shut_down = true;
                        self.send(Response::new_ok(req.id, ()).into());
                        continue;
                    }
                    let (id, method) = (req.id.clone(), req.method.clone());
                    let answered = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                        self.request(req)
                    }));
                    if answered.is_err() {
                        let msg =
                            format!("chasles lsp failed on {method} (a bug: please report it)");
                        self.send(
                            Response::new_err(id, ErrorCode::InternalError as i32, msg).into(),
                        );
                    }
                }
                Message::Notification(n) if n.method == "exit" => {
                    return if shut_down { 0 } else { 1 };
                }
                Message::Notification(n) => self.notification(n),
                Message::Response(_) => {}
            }
        }
    }

    fn send(&self, msg: Message) {
        let _ = self.conn.sender.send(msg);
    }

    fn reply_err(&self, req: Request, code: ErrorCode, msg: &str) {
        self.send(Response::new_err(req.id, code as i32, msg.into()).into());
    }

    /// Checks the documents whose changes are due, and publishes.
    fn check_due(&mut self) {
        let now = Instant::now();
        let due: Vec<Uri> = self
            .docs
            .iter()
            .filter(|(_, o)| o.due.is_some_and(|t| t <= now))
            .map(|(u, _)| u.clone())
            .collect();
        for uri in due {
            self.check(&uri);
        }
    }

    /// Checks `uri` now (if it changed since its last check) and publishes
    /// its diagnostics.
    fn check(&mut self, uri: &Uri) {
        let settings = self.settings;
        let enc = self.enc;
        let Some(open) = self.docs.get_mut(uri) else {
            return;
        };
        if open.analysis.is_some() {
            return;
        }
        let text = &open.doc.text;
        let analysis = std::panic::catch_unwind(|| Analysis::of(text, settings))
            .unwrap_or_else(|_| Analysis::failed(text));
        open.due = None;
        let diagnostics = analysis
            .diagnostics
            .iter()
            .map(|d| features::diagnostic(d, &open.doc, uri, enc))
            .collect();
        let params =
            PublishDiagnosticsParams::new(uri.clone(), diagnostics, Some(open.doc.version));
        open.analysis = Some(analysis);
        self.send(Notification::new(PublishDiagnostics::METHOD.into(), params).into());
    }

    fn notification(&mut self, n: Notification) {
        match n.method.as_str() {
            DidOpenTextDocument::METHOD => {
                let Ok(p) =
                    n.extract::<lsp_types::DidOpenTextDocumentParams>(DidOpenTextDocument::METHOD)
                else {
                    return;
                };
                let uri = p.text_document.uri;
                self.docs.insert(
                    uri.clone(),
                    Open {
                        doc: Document::new(p.text_document.text, p.text_document.version),
                        analysis: None,
                        due: None,
                    },
                );
                self.check(&uri);
            }
            DidChangeTextDocument::METHOD => {
                let Ok(p) = n.extract::<lsp_types::DidChangeTextDocumentParams>(
                    DidChangeTextDocument::METHOD,
                ) else {
                    return;
                };
                let enc = self.enc;
                if let Some(open) = self.docs.get_mut(&p.text_document.uri) {
                    for c in &p.content_changes {
                        open.doc.apply(c, enc);
                    }
                    open.doc.version = p.text_document.version;
                    open.analysis = None;
                    open.due = Some(Instant::now() + DEBOUNCE);
                }
            }
            DidCloseTextDocument::METHOD => {
                let Ok(p) = n
                    .extract::<lsp_types::DidCloseTextDocumentParams>(DidCloseTextDocument::METHOD)
                else {
                    return;
                };
                let uri = p.text_document.uri;
                if self.docs.remove(&uri).is_some() {
                    let params = PublishDiagnosticsParams::new(uri, Vec::new(), None);
                    self.send(Notification::new(PublishDiagnostics::METHOD.into(), params).into());
                }
            }
            _ => {}
        }
    }

    /// The document and its fresh check for a request at a position.
    fn at(&mut self, p: &TextDocumentPositionParams) -> Option<(&Open, usize)> {
        let uri = &p.text_document.uri;
        self.check(uri);
        let open = self.docs.get(uri)?;
        let offset = open.doc.offset(p.position, self.enc);
        Some((open, offset))
    }

    fn request(&mut self, req: Request) {
        let enc = self.enc;
        let result = match req.method.as_str() {
            HoverRequest::METHOD => {
                let Ok(p) = serde_json::from_value::<lsp_types::HoverParams>(req.params.clone())
                else {
                    return self.reply_err(req, ErrorCode::InvalidParams, "bad hover params");
                };
                let settings = self.settings;
                let hover = self
                    .at(&p.text_document_position_params)
                    .and_then(|(o, at)| {
                        features::hover(&o.doc, o.analysis.as_ref()?, at, enc, settings)
                    });
                serde_json::to_value(hover)
            }
            Completion::METHOD => {
                let Ok(p) =
                    serde_json::from_value::<lsp_types::CompletionParams>(req.params.clone())
                else {
                    return self.reply_err(req, ErrorCode::InvalidParams, "bad completion params");
                };
                let settings = self.settings;
                let items = self
                    .at(&p.text_document_position)
                    .and_then(|(o, at)| {
                        Some(features::completion(
                            &o.doc,
                            o.analysis.as_ref()?,
                            at,
                            settings,
                        ))
                    })
                    .unwrap_or_default();
                serde_json::to_value(CompletionResponse::Array(items))
            }
            GotoDefinition::METHOD => {
                let Ok(p) =
                    serde_json::from_value::<lsp_types::GotoDefinitionParams>(req.params.clone())
                else {
                    return self.reply_err(req, ErrorCode::InvalidParams, "bad definition params");
                };
                let uri = p.text_document_position_params.text_document.uri.clone();
                let loc = self
                    .at(&p.text_document_position_params)
                    .and_then(|(o, at)| {
                        features::definition(&o.doc, o.analysis.as_ref()?, at, &uri, enc)
                    });
                serde_json::to_value(loc.map(GotoDefinitionResponse::Scalar))
            }
            DocumentSymbolRequest::METHOD => {
                let Ok(p) =
                    serde_json::from_value::<lsp_types::DocumentSymbolParams>(req.params.clone())
                else {
                    return self.reply_err(req, ErrorCode::InvalidParams, "bad symbol params");
                };
                let uri = p.text_document.uri;
                self.check(&uri);
                let symbols = self
                    .docs
                    .get(&uri)
                    .and_then(|o| Some(features::symbols(&o.doc, o.analysis.as_ref()?, enc)));
                serde_json::to_value(symbols.map(DocumentSymbolResponse::Nested))
            }
            _ => {
                return self.reply_err(
                    req.clone(),
                    ErrorCode::MethodNotFound,
                    &format!("chasles lsp does not answer {}", req.method),
                );
            }
        };
        match result {
            Ok(v) => self.send(Response::new_ok(req.id, v).into()),
            Err(e) => self.reply_err(req, ErrorCode::InternalError, &e.to_string()),
        }
    }
}
