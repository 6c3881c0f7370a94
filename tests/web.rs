//! The explorer as a web page, in a real browser: `tools/web.sh build` writes the page,
//! a server in this test serves it on 127.0.0.1, and headless Chromium opens it through
//! chromedriver, on SwiftShader's WebGPU adapter, with the four flags its canvas needs.
//!
//! - The default view is not blank: the screenshot holds the explorer's light text and
//!   pixels, and the same check rejects the canvas Chromium shows with
//!   `--enable-unsafe-webgpu` alone (the page says `· ready` there, but composites
//!   nothing: a silent false pass for a check on the title alone).
//! - A link copied from the desktop explorer opens the same view on the page: at the
//!   focus, each pane's coverage read back from the page equals what the native
//!   `glyphscope render --case …` draws there (the values `--magnify 32` writes in its
//!   blocks), within one 8-bit step.
//! - A malformed fragment opens the default view and says what is wrong.
//!
//! Needs Chromium and its driver (`apt-get install chromium chromium-driver`), the
//! wasm32 target and wasm-bindgen-cli (`tools/web.sh build` says which version);
//! `tools/setup.sh` installs them. Without them these tests fail with the message saying so.

mod common;
#[path = "common/explorer.rs"]
mod explorer;

use std::io::{BufRead, BufReader, Read, Write};
use std::net::{TcpListener, TcpStream};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::{Mutex, OnceLock};
use std::time::{Duration, Instant};

use base64::Engine;
use explorer::{harness, settle};
use glyphscope::app::settings::{PaneSource, Settings};
use glyphscope::coverage::CoverageImage;
use glyphscope::coverage::Png as _;
use image::RgbaImage;
use serde_json::{Value, json};

/// Everything a working canvas needs in headless Chromium on a machine with no GPU.
const FLAGS: [&str; 4] = [
    "--enable-unsafe-webgpu",
    "--enable-features=Vulkan",
    "--use-vulkan=swiftshader",
    "--use-angle=swiftshader",
];

/// Time for the page to load, compile its wasm and draw its first frame on SwiftShader
/// (about 20 s on 2 cores), and for a view to rest and be analysed.
const READY_WITHIN: Duration = Duration::from_secs(240);

/// The page, built once for the test binary; the address it is served at.
fn page() -> &'static str {
    static PAGE: OnceLock<String> = OnceLock::new();
    PAGE.get_or_init(|| {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        // Its progress and errors go to the terminal: a cold build takes minutes.
        let built = Command::new("sh")
            .arg(root.join("tools/web.sh"))
            .arg("build")
            .stdout(Stdio::null())
            .status()
            .expect("sh runs tools/web.sh");
        assert!(built.success(), "tools/web.sh build failed (above)");
        serve(root.join("target/web"))
    })
}

/// Serves the files of `dir` on 127.0.0.1 (a port of its own), from a thread that lives
/// as long as the test binary; returns the address.
fn serve(dir: PathBuf) -> String {
    let listener = TcpListener::bind("127.0.0.1:0").expect("a local port");
    let address = format!("http://{}/", listener.local_addr().unwrap());
    std::thread::spawn(move || {
        for stream in listener.incoming().flatten() {
            let dir = dir.clone();
            std::thread::spawn(move || answer(stream, &dir));
        }
    });
    address
}

/// Answers one GET with the file it names, or 404.
fn answer(mut stream: TcpStream, dir: &Path) {
    let mut request_line = String::new();
    let mut reader = BufReader::new(stream.try_clone().unwrap());
    if reader.read_line(&mut request_line).is_err() {
        return;
    }
    // The headers are read and ignored.
    let mut line = String::new();
    while reader.read_line(&mut line).is_ok_and(|n| n > 2) {
        line.clear();
    }
    let path = request_line.split_whitespace().nth(1).unwrap_or("/");
    let path = path.split(['?', '#']).next().unwrap_or("/");
    let name = match path.trim_start_matches('/') {
        "" => "index.html",
        name if !name.contains("..") => name,
        _ => "",
    };
    let (status, body, kind) = match std::fs::read(dir.join(name)) {
        Ok(body) if !name.is_empty() => {
            let kind = match Path::new(name).extension().and_then(|e| e.to_str()) {
                Some("html") => "text/html; charset=utf-8",
                Some("js") => "text/javascript",
                // Streaming compilation needs this type.
                Some("wasm") => "application/wasm",
                _ => "application/octet-stream",
            };
            ("200 OK", body, kind)
        }
        _ => ("404 Not Found", b"not found".to_vec(), "text/plain"),
    };
    let head = format!(
        "HTTP/1.1 {status}\r\nContent-Type: {kind}\r\nContent-Length: {}\r\nConnection: close\r\n\r\n",
        body.len()
    );
    stream.write_all(head.as_bytes()).ok();
    stream.write_all(&body).ok();
}

/// The Chromium binary on the PATH (Debian's package installs `chromium`).
fn chromium() -> String {
    std::env::var_os("PATH")
        .iter()
        .flat_map(std::env::split_paths)
        .map(|dir| dir.join("chromium"))
        .find(|path| path.is_file())
        .unwrap_or_else(|| {
            panic!("no chromium on the PATH: apt-get install chromium (tools/setup.sh does)")
        })
        .display()
        .to_string()
}

/// A headless Chromium driven through chromedriver's W3C endpoint.
struct Browser {
    driver: Child,
    port: u16,
    session: String,
    /// This browser's turn, given up after the browser is closed (`Drop`).
    _turn: std::sync::MutexGuard<'static, ()>,
}

impl Browser {
    /// Starts Chromium with `flags`. One browser at a time: SwiftShader on 2 cores is
    /// slow enough alone.
    fn start(flags: &[&str]) -> Browser {
        static ONE_AT_A_TIME: Mutex<()> = Mutex::new(());
        let turn = ONE_AT_A_TIME.lock().unwrap_or_else(|p| p.into_inner());
        let port = TcpListener::bind("127.0.0.1:0")
            .and_then(|l| l.local_addr())
            .expect("a free port")
            .port();
        let driver = Command::new("chromedriver")
            .arg(format!("--port={port}"))
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap_or_else(|e| {
                panic!(
                    "chromedriver cannot start ({e}): apt-get install chromium chromium-driver (tools/setup.sh does)"
                )
            });
        let mut browser = Browser {
            driver,
            port,
            session: String::new(),
            _turn: turn,
        };
        let start = Instant::now();
        while browser.call("GET", "/status", None).is_err() {
            assert!(
                start.elapsed() < Duration::from_secs(30),
                "chromedriver never answered"
            );
            std::thread::sleep(Duration::from_millis(100));
        }
        let mut args = vec!["--headless=new", "--no-sandbox", "--window-size=1280,800"];
        args.extend_from_slice(flags);
        let capabilities = json!({"capabilities": {"alwaysMatch": {
            "browserName": "chrome",
            "goog:chromeOptions": {"binary": chromium(), "args": args},
        }}});
        let session = browser
            .call("POST", "/session", Some(capabilities))
            .unwrap_or_else(|e| panic!("Chromium did not start: {e}"));
        browser.session = session["sessionId"].as_str().unwrap().to_owned();
        browser
    }

    /// One WebDriver command; its `value`, or the error it answered.
    fn call(&self, method: &str, path: &str, body: Option<Value>) -> Result<Value, String> {
        let stream = TcpStream::connect(("127.0.0.1", self.port)).map_err(|e| e.to_string())?;
        // A command that never answers fails the test instead of hanging it.
        stream.set_read_timeout(Some(READY_WITHIN)).ok();
        let body = body.map(|b| b.to_string()).unwrap_or_default();
        let request = format!(
            "{method} {path} HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\nContent-Length: {}\r\n\r\n{body}",
            body.len()
        );
        (&stream)
            .write_all(request.as_bytes())
            .map_err(|e| e.to_string())?;
        // chromedriver keeps the connection open: the answer is as long as it says.
        let mut reader = BufReader::new(&stream);
        let (mut line, mut status, mut length) = (String::new(), String::new(), 0);
        loop {
            line.clear();
            reader.read_line(&mut line).map_err(|e| e.to_string())?;
            let header = line.trim_end();
            if header.is_empty() {
                break;
            }
            if status.is_empty() {
                status = header.to_owned();
            } else if let Some((name, value)) = header.split_once(':')
                && name.eq_ignore_ascii_case("content-length")
            {
                length = value
                    .trim()
                    .parse()
                    .map_err(|_| format!("bad length: {header}"))?;
            }
        }
        let mut body = vec![0; length];
        reader.read_exact(&mut body).map_err(|e| e.to_string())?;
        let answer: Value = serde_json::from_slice(&body)
            .map_err(|e| format!("{e}: {}", String::from_utf8_lossy(&body)))?;
        if !status.contains(" 200 ") {
            return Err(answer["value"].to_string());
        }
        Ok(answer["value"].clone())
    }

    fn command(&self, method: &str, what: &str, body: Option<Value>) -> Value {
        let path = format!("/session/{}/{what}", self.session);
        self.call(method, &path, body)
            .unwrap_or_else(|e| panic!("{what}: {e}"))
    }

    /// Opens the page at `fragment` and waits until its title ends in `· ready`; the
    /// title then.
    fn open(&self, fragment: &str) -> String {
        // A fresh load each time: a new fragment on the same page would only be an
        // event to the page already open.
        self.command("POST", "url", Some(json!({"url": "about:blank"})));
        self.command(
            "POST",
            "url",
            Some(json!({"url": format!("{}{fragment}", page())})),
        );
        let start = Instant::now();
        loop {
            let title = self.command("GET", "title", None);
            let title = title.as_str().unwrap_or_default().to_owned();
            if title.ends_with("· ready") || title.contains("· error:") {
                return title;
            }
            assert!(
                start.elapsed() < READY_WITHIN,
                "the page never said ready: '{title}'"
            );
            std::thread::sleep(Duration::from_millis(500));
        }
    }

    /// The value of a script run in the page.
    fn run(&self, script: &str) -> Value {
        self.command(
            "POST",
            "execute/sync",
            Some(json!({"script": script, "args": []})),
        )
    }

    fn body_data(&self, name: &str) -> String {
        let value = self.run(&format!("return document.body.dataset.{name} || ''"));
        value.as_str().unwrap_or_default().to_owned()
    }

    /// What the page shows, as a person would see it.
    fn screenshot(&self) -> RgbaImage {
        let png = self.command("GET", "screenshot", None);
        let bytes = base64::engine::general_purpose::STANDARD
            .decode(png.as_str().unwrap())
            .unwrap();
        image::load_from_memory(&bytes).unwrap().to_rgba8()
    }

    /// The numbers of the first view at rest (`data-view`) that `wanted` accepts.
    fn view_where(&self, what: &str, wanted: impl Fn(&Value) -> bool) -> Value {
        let start = Instant::now();
        loop {
            let numbers = self.body_data("view");
            if let Ok(view) = serde_json::from_str::<Value>(&numbers)
                && wanted(&view)
            {
                return view;
            }
            assert!(
                start.elapsed() < READY_WITHIN,
                "never {what}; the page shows {numbers:.300}, says '{}'",
                self.body_data("status")
            );
            std::thread::sleep(Duration::from_millis(500));
        }
    }

    /// The numbers of the view at rest whose link is `link`.
    fn view_numbers(&self, link: &str) -> Value {
        self.view_where(&format!("the view {link} at rest"), |view| {
            view["link"] == *link
        })
    }

    /// The address's fragment.
    fn fragment(&self) -> String {
        self.run("return location.hash")
            .as_str()
            .unwrap_or_default()
            .to_owned()
    }
}

impl Drop for Browser {
    fn drop(&mut self) {
        let path = format!("/session/{}", self.session);
        self.call("DELETE", &path, None).ok();
        self.driver.kill().ok();
        self.driver.wait().ok();
    }
}

/// Whether a screenshot shows the explorer: its panels' light text and the panes' pixels
/// make at least 1% of it light and many distinct greys; a canvas that composited
/// nothing is one colour (black, or the page's background through a transparent one).
fn shows_the_explorer(screen: &RgbaImage) -> Result<(), String> {
    let luma = |p: &image::Rgba<u8>| {
        (u32::from(p[0]) * 299 + u32::from(p[1]) * 587 + u32::from(p[2]) * 114) / 1000
    };
    let total = screen.pixels().count();
    let light = screen.pixels().filter(|p| luma(p) > 128).count();
    let mut greys = [false; 256];
    for p in screen.pixels() {
        greys[luma(p) as usize] = true;
    }
    let distinct = greys.iter().filter(|&&g| g).count();
    if light * 100 < total || distinct < 32 {
        return Err(format!(
            "the page looks blank: {light} of {total} pixels light, {distinct} distinct greys"
        ));
    }
    Ok(())
}

#[test]
fn the_page_draws_the_explorer_and_a_blank_canvas_fails_the_check() {
    let browser = Browser::start(&FLAGS);
    let title = browser.open("");
    assert!(title.ends_with("· ready"), "{title}");
    // A first start, at rest: on sdf-cells' worst pixel, its numbers in. This is the
    // README's picture of the page (screenshots/web-page.png is a copy of it).
    browser.view_where("the first start at rest", |_| true);
    let screen = browser.screenshot();
    shows_the_explorer(&screen).unwrap();
    let picture = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/web-page.png");
    screen.save(&picture).unwrap();
    drop(browser);

    // The flag that makes an adapter exist, without the ones that make the canvas
    // composite: the title still says ready, and only the pixels tell.
    let browser = Browser::start(&FLAGS[..1]);
    let title = browser.open("");
    assert!(title.ends_with("· ready"), "{title}");
    let blank = browser.screenshot();
    let verdict = shows_the_explorer(&blank);
    assert!(
        verdict.is_err(),
        "the check passes a canvas Chromium cannot show"
    );
}

/// The address is the link: it follows the view; a fragment typed into it opens its
/// view; a font the page reads (as its file picker and a drop hand it over) opens, and
/// the address then drops the fragment, which cannot carry that font.
#[test]
fn the_address_follows_the_view_and_the_page_opens_fragments_and_fonts() {
    let browser = Browser::start(&FLAGS);
    let title = browser.open("");
    assert!(title.ends_with("· ready"), "{title}");
    let first = browser.view_where("a first view at rest", |view| view["link"] != "");
    assert_eq!(browser.fragment(), first["link"].as_str().unwrap());

    browser.run("location.hash = '#case=strong-skew&a=winding&magnify=32'");
    let typed = browser.view_where("the typed case at rest", |view| {
        view["link"]
            .as_str()
            .unwrap()
            .starts_with("#case=strong-skew&")
    });
    let link = typed["link"].as_str().unwrap();
    assert!(
        link.contains("&a=winding&") && link.contains("&magnify=32&"),
        "{link}"
    );
    assert_eq!(browser.fragment(), link);

    let font =
        std::fs::read(Path::new(env!("CARGO_MANIFEST_DIR")).join("fonts/lmroman10-regular.otf"))
            .unwrap();
    let encoded = base64::engine::general_purpose::STANDARD.encode(font);
    browser.command(
        "POST",
        "execute/sync",
        Some(json!({
            "script": "window.glyphscope.open_font('lmroman10-regular.otf', \
                Uint8Array.from(atob(arguments[0]), c => c.charCodeAt(0)))",
            "args": [encoded],
        })),
    );
    browser.view_where("the opened font's view at rest", |view| view["link"] == "");
    assert_eq!(
        browser.fragment(),
        "",
        "a link cannot carry a font from this computer"
    );
    shows_the_explorer(&browser.screenshot()).unwrap();
}

#[test]
fn a_malformed_link_opens_the_default_view_and_says_what_is_wrong() {
    let browser = Browser::start(&FLAGS);
    let title = browser.open("#case=inter-overlaps&size=-4");
    assert!(title.ends_with("· ready"), "{title}");
    let status = browser.body_data("status");
    assert!(
        status.contains("size=-4") && status.contains("is not positive"),
        "the status line says '{status}'"
    );
    shows_the_explorer(&browser.screenshot()).unwrap();
}

/// The desktop explorer's link to `case` with pane A drawing `method`, magnified ×32 on
/// its worst pixel as loading a case does; the pixel it is magnified on, and the frame
/// pixel at the pane's (0, 0) (`render --case` draws the frame; the pane shows a window
/// of it).
fn desktop_link(case: &str, method: &str) -> (String, (u32, u32), (i64, i64)) {
    let mut settings = Settings::default();
    settings.panes[0].source = PaneSource::Method {
        name: method.into(),
        params: Vec::new(),
    };
    let mut desktop = harness(settings);
    settle(&mut desktop);
    desktop.state_mut().load_case(case);
    settle(&mut desktop);
    let window = desktop.state().magnified_window().unwrap();
    assert_eq!(window.factor, 32);
    let frame = desktop
        .state()
        .settings
        .camera
        .case_frame
        .expect("a case has a frame");
    let offset = frame.offset.map(|v| {
        assert_eq!(v.fract(), 0.0, "a whole-pixel window of the frame");
        v as i64
    });
    (
        desktop.state().link().expect("a case travels in a link"),
        window.focus,
        (offset[0], offset[1]),
    )
}

/// What `glyphscope render --case CASE --method METHOD` draws.
fn native_render(case: &str, method: &str, dir: &Path) -> CoverageImage {
    let out = dir.join(format!("{case}-{method}.png"));
    let run = Command::new(env!("CARGO_BIN_EXE_glyphscope"))
        .args(["render", "--case", case, "--method", method, "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    CoverageImage::load_png(&out).unwrap()
}

/// Coverage as the 8-bit value a PNG stores (as `render --out` writes it).
fn byte(coverage: f32) -> i32 {
    let one = CoverageImage {
        width: 1,
        height: 1,
        data: vec![coverage],
    };
    i32::from(one.to_gray8().get_pixel(0, 0)[0])
}

#[test]
fn a_desktop_link_opens_the_same_pixels_at_the_focus_on_the_page() {
    let dir = std::env::temp_dir().join(format!("glyphscope-web-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut links = Vec::new();
    for (case, method) in [("inter-overlaps", "sdf-cells"), ("strong-skew", "winding")] {
        links.push((case, method, desktop_link(case, method)));
    }
    let browser = Browser::start(&FLAGS);
    for (case, method, (link, desktop_focus, offset)) in links {
        let title = browser.open(&link);
        assert!(title.ends_with("· ready"), "{title}");
        let view = browser.view_numbers(&link);
        let window = &view["window"];
        let (x0, y0, cols) = (
            window["x0"].as_u64().unwrap() as u32,
            window["y0"].as_u64().unwrap() as u32,
            window["cols"].as_u64().unwrap() as u32,
        );
        let rows = window["rows"].as_u64().unwrap() as u32;
        // In pane pixels, and in the frame's.
        let focus = (
            window["focus"][0].as_i64().unwrap(),
            window["focus"][1].as_i64().unwrap(),
        );
        assert!(
            (i64::from(x0)..i64::from(x0 + cols)).contains(&focus.0)
                && (i64::from(y0)..i64::from(y0 + rows)).contains(&focus.1),
            "{link}: the window holds its focus"
        );
        let in_frame = (focus.0 + offset.0, focus.1 + offset.1);
        assert_eq!(window["factor"], 32, "{link}");

        assert_eq!(
            (focus.0 as u32, focus.1 as u32),
            desktop_focus,
            "{link}: the page is magnified where the desktop was"
        );
        let drawn = native_render(case, method, &dir);
        let reference = native_render(case, "reference", &dir);
        let pane = view["panes"]
            .as_array()
            .unwrap()
            .iter()
            .find(|p| p[0] == "A")
            .unwrap_or_else(|| panic!("{link}: pane A has no numbers: {view}"));
        assert_eq!(pane[1], method);
        let page_pixels: Vec<f32> = serde_json::from_value(pane[2].clone()).unwrap();
        let page_reference: Vec<f32> = serde_json::from_value(view["reference"].clone()).unwrap();
        assert_eq!(page_pixels.len() as u32, cols * rows);
        assert_eq!(page_reference.len() as u32, cols * rows);
        // Every pixel of the page's window that the frame holds: the focus and what
        // the magnifier shows around it.
        let mut compared = 0;
        for y in 0..rows {
            for x in 0..cols {
                let (fx, fy) = (i64::from(x0 + x) + offset.0, i64::from(y0 + y) + offset.1);
                let in_frame = (0..i64::from(drawn.width)).contains(&fx)
                    && (0..i64::from(drawn.height)).contains(&fy);
                if !in_frame {
                    continue;
                }
                let at = (y * cols + x) as usize;
                let (fx, fy) = (fx as u32, fy as u32);
                for (what, page, native) in [
                    (method, page_pixels[at], drawn.get(fx, fy)),
                    ("reference", page_reference[at], reference.get(fx, fy)),
                ] {
                    let (page_byte, native_byte) = (byte(page), byte(native));
                    assert!(
                        page.is_finite() && (page_byte - native_byte).abs() <= 1,
                        "{link}: {what} at frame pixel ({fx}, {fy}): page {page} ({page_byte}/255), native {native} ({native_byte}/255)"
                    );
                }
                compared += 1;
            }
        }
        assert!(
            compared >= 9,
            "{link}: only {compared} pixels around the focus"
        );
        println!(
            "{case}: {method} and the reference within one 8-bit step of the native render on {compared} pixels around frame pixel {in_frame:?}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}
