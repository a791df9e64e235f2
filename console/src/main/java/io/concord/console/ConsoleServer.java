package io.concord.console;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpServer;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.URLDecoder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.LongAdder;

/**
 * The console's HTTP side, on the JDK's server with a fixed pool of threads: one per open event
 * stream (at most the hub's limit) and four for everything else. No handler touches an agent:
 * reads come from the hub's last events, the writes (a view's action, start, kill, send) are handed to the loop.
 */
final class ConsoleServer {
    static final int MAX_URI = 2_048;
    static final int MAX_BODY = 4_096;
    static final long KEEPALIVE_MS = 2_000;
    private static final Set<String> TOPICS = Set.of("platform", "safety", "sniff", "mail");

    private final HttpServer http;
    private final ExecutorService pool;
    private final String token;
    private final boolean open;
    private final Hub hub;
    private final Console console;
    private final ObjectMapper json = new ObjectMapper();
    private final Map<String, LongAdder> refusals = new ConcurrentHashMap<>();
    private volatile boolean stopping;

    ConsoleServer(InetSocketAddress at, String token, boolean open, Hub hub, Console console) throws IOException {
        this.token = token;
        this.open = open;
        this.hub = hub;
        this.console = console;
        this.http = HttpServer.create(at, 64);
        AtomicInteger n = new AtomicInteger();
        this.pool = Executors.newFixedThreadPool(console.config().maxBrowsers() + 4, r -> {
            Thread t = new Thread(r, "concord-console-" + n.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
        http.setExecutor(pool);
        http.createContext("/", this::handle);
    }

    void start() {
        http.start();
    }

    void stop() {
        stopping = true;
        http.stop(0);
        pool.shutdownNow();
    }

    InetSocketAddress address() {
        return http.getAddress();
    }

    Map<String, Long> refusals() {
        Map<String, Long> m = new TreeMap<>();
        refusals.forEach((k, v) -> m.put(k, v.sum()));
        return m;
    }

    private void handle(HttpExchange x) throws IOException {
        try {
            route(x);
        } catch (RuntimeException e) {
            answer(x, 500, "text/plain", "the console failed on this request: " + e);
        } finally {
            x.close();
        }
    }

    private void route(HttpExchange x) throws IOException {
        String raw = x.getRequestURI().getRawPath();
        String rawQuery = x.getRequestURI().getRawQuery();
        if (raw.length() + (rawQuery == null ? 0 : rawQuery.length()) > MAX_URI) {
            refuse(x, 414, "the address is longer than " + MAX_URI + " characters");
            return;
        }
        Map<String, String> q;
        try {
            q = query(rawQuery);
        } catch (IllegalArgumentException e) {
            refuse(x, 400, "a malformed query: " + e.getMessage());
            return;
        }
        if (!authorized(x, q)) {
            x.getResponseHeaders().set("WWW-Authenticate", "Bearer realm=\"concord-console\"");
            refuse(x, 401, "this console is open on a network address: every request needs its token "
                    + "(?token=..., the Authorization: Bearer header, or the concord-token cookie), printed when it started");
            return;
        }
        if (!open && !loopbackHost(x.getRequestHeaders().getFirst("Host"))) {
            refuse(x, 403, "this console answers only to the names of the loopback address (Host: 127.0.0.1, localhost or [::1])");
            return;
        }
        String method = x.getRequestMethod();
        String path = raw;
        if (method.equals("POST")) {
            if (path.startsWith("/api/views/")) {
                act(x, path.substring("/api/views/".length()));
            } else if (path.startsWith("/api/agents/")) {
                agentAction(x, path.substring("/api/agents/".length()));
            } else if (path.equals("/api/record/start") || path.equals("/api/record/stop")) {
                record(x, path.endsWith("start"));
            } else {
                refuse(x, 405, "only an action may be posted: a view's at /api/views/{view}/{action}, "
                        + "the console's at /api/agents/start, /api/agents/kill, /api/agents/send, /api/record/start and /api/record/stop");
            }
            return;
        }
        if (!method.equals("GET") && !method.equals("HEAD")) {
            refuse(x, 405, "the console answers GET, and POST for a view's action");
            return;
        }
        switch (path) {
            case "/", "/index.html" -> resource(x, "index.html", "text/html; charset=utf-8", q);
            case "/app.js" -> resource(x, "app.js", "text/javascript; charset=utf-8", q);
            case "/style.css" -> resource(x, "style.css", "text/css; charset=utf-8", q);
            case "/api/events" -> events(x, q);
            case "/api/platform", "/api/safety", "/api/mail" -> last(x, path.substring(5));
            case "/api/views" -> views(x);
            case "/api/bench" -> benchList(x);
            case "/api/drops" -> answer(x, 200, "application/json", json.writeValueAsString(console.drops()));
            case "/api/recordings" -> recordings(x);
            case "/favicon.ico" -> answer(x, 204, "image/x-icon", new byte[0]);   // none: not a 404 each page load
            default -> {
                if (path.startsWith("/api/recordings/")) {
                    recordingFile(x, path.substring("/api/recordings/".length()));
                } else if (path.startsWith("/api/bench/")) {
                    benchFile(x, path.substring("/api/bench/".length()));
                } else {
                    refuse(x, 404, "no such page: " + path + "; the console serves /, /api/events, /api/platform, "
                            + "/api/safety, /api/mail, /api/views, /api/bench, /api/recordings");
                }
            }
        }
    }

    private boolean authorized(HttpExchange x, Map<String, String> q) {
        if (token == null) {
            return true;
        }
        String given = q.get("token");
        String auth = x.getRequestHeaders().getFirst("Authorization");
        if (given == null && auth != null && auth.startsWith("Bearer ")) {
            given = auth.substring(7).trim();
        }
        if (given == null) {
            String cookies = x.getRequestHeaders().getFirst("Cookie");
            if (cookies != null) {
                for (String c : cookies.split(";")) {
                    String t = c.trim();
                    if (t.startsWith("concord-token=")) {
                        given = t.substring("concord-token=".length());
                    }
                }
            }
        }
        return given != null && MessageDigest.isEqual(given.getBytes(StandardCharsets.UTF_8), token.getBytes(StandardCharsets.UTF_8));
    }

    /** On loopback, a page of another site cannot reach the console through a name it controls (DNS rebinding). */
    static boolean loopbackHost(String host) {
        if (host == null) {
            return false;
        }
        String h = host.trim().toLowerCase(java.util.Locale.ROOT);
        int colon = h.lastIndexOf(':');
        if (colon > 0 && !h.endsWith("]")) {
            h = h.substring(0, colon);
        }
        return h.equals("127.0.0.1") || h.equals("localhost") || h.equals("[::1]");
    }

    private void resource(HttpExchange x, String name, String type, Map<String, String> q) throws IOException {
        try (InputStream in = ConsoleServer.class.getResourceAsStream("web/" + name)) {
            if (in == null) {
                refuse(x, 404, "the console's " + name + " is missing from its jar");
                return;
            }
            byte[] b = in.readAllBytes();
            if (token != null && q.containsKey("token")) {
                x.getResponseHeaders().add("Set-Cookie", "concord-token=" + token + "; Path=/; HttpOnly; SameSite=Strict");
            }
            x.getResponseHeaders().set("Content-Security-Policy", "default-src 'self'; img-src 'self' data:; style-src 'self'");
            answer(x, 200, type, b);
        }
    }

    private void last(HttpExchange x, String topic) throws IOException {
        String json = hub.last(topic);
        answer(x, 200, "application/json", json == null ? "null" : json);
    }

    private void views(HttpExchange x) throws IOException {
        ArrayNode a = json.createArrayNode();
        for (ConsoleView v : console.views()) {
            ObjectNode o = a.addObject().put("id", v.id()).put("title", v.title());
            ArrayNode acts = o.putArray("actions");
            v.actions().forEach(acts::add);
        }
        answer(x, 200, "application/json", a.toString());
    }

    private void events(HttpExchange x, Map<String, String> q) throws IOException {
        Set<String> topics = new LinkedHashSet<>();
        for (String t : q.getOrDefault("topics", "platform").split(",")) {
            String s = t.trim();
            if (s.isEmpty()) {
                continue;
            }
            boolean view = s.startsWith("view-") && console.views().stream().anyMatch(v -> ("view-" + v.id()).equals(s));
            if (!TOPICS.contains(s) && !view) {
                refuse(x, 400, "no such topic '" + s + "'; topics are platform, safety, sniff, mail and view-{id} of /api/views");
                return;
            }
            topics.add(s);
        }
        Set<String> sniff = new LinkedHashSet<>();
        for (String a : q.getOrDefault("sniff", "").split(",")) {
            if (!a.isBlank()) {
                if (a.length() > 256) {
                    refuse(x, 400, "an agent name in sniff is longer than 256 characters");
                    return;
                }
                sniff.add(a.trim());
            }
        }
        if (sniff.size() > ConsoleAgent.MAX_SNIFFED) {
            refuse(x, 400, "at most " + ConsoleAgent.MAX_SNIFFED + " agents may be sniffed at once, got " + sniff.size());
            return;
        }
        String conv = q.get("conversation");
        Hub.Client c = hub.open(topics, sniff, conv == null || conv.isBlank() ? null : conv);
        if (c == null) {
            refuse(x, 503, "too many browsers have the console open (" + console.config().maxBrowsers() + "); close one");
            return;
        }
        try {
            x.getResponseHeaders().set("Content-Type", "text/event-stream; charset=utf-8");
            x.getResponseHeaders().set("Cache-Control", "no-store");
            x.sendResponseHeaders(200, 0);
            OutputStream out = x.getResponseBody();
            out.write(": concord console\n\n".getBytes(StandardCharsets.UTF_8));
            out.flush();
            while (!stopping && !c.closed) {
                String e = c.take(KEEPALIVE_MS);
                out.write((e == null ? ": keep-alive\n\n" : e).getBytes(StandardCharsets.UTF_8));
                out.flush();   // a browser that has gone makes this throw; a slow one blocks this thread only
            }
        } catch (IOException e) {
            // the browser went away
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            hub.close(c);
        }
    }

    private void act(HttpExchange x, String rest) throws IOException {
        if (!fromThePage(x)) {
            return;
        }
        int slash = rest.indexOf('/');
        ConsoleView view = null;
        String action = slash < 0 ? "" : rest.substring(slash + 1);
        for (ConsoleView v : console.views()) {
            if (slash > 0 && v.id().equals(rest.substring(0, slash))) {
                view = v;
            }
        }
        if (view == null || !view.actions().contains(action)) {
            refuse(x, 404, "no such action: " + rest + "; see /api/views");
            return;
        }
        ConsoleView v = view;
        onLoop(x, params -> v.act(action, params));
    }

    /** Starting, killing and messaging agents (JADE's RMA and DummyAgent): the same guards as a view's action. */
    private void agentAction(HttpExchange x, String action) throws IOException {
        if (!fromThePage(x)) {
            return;
        }
        if (!ConsoleAgent.ACTIONS.contains(action)) {
            refuse(x, 404, "no such action: " + action + "; the console's are " + ConsoleAgent.ACTIONS);
            return;
        }
        onLoop(x, params -> console.agentAction(action, params));
    }

    private boolean fromThePage(HttpExchange x) throws IOException {
        if (!"1".equals(x.getRequestHeaders().getFirst("X-Concord-Console"))) {
            refuse(x, 403, "an action must carry the header X-Concord-Console: 1 (the page sends it; another site's form cannot)");
            return false;
        }
        return true;
    }

    /** An action's form parameters, or null once refused (413 over {@value #MAX_BODY} bytes, 400 malformed). */
    private Map<String, String> form(HttpExchange x) throws IOException {
        byte[] body = readBody(x);
        if (body == null) {
            refuse(x, 413, "an action takes at most " + MAX_BODY + " bytes of form parameters");
            return null;
        }
        try {
            return query(new String(body, StandardCharsets.UTF_8));
        } catch (IllegalArgumentException e) {
            refuse(x, 400, "malformed form parameters: " + e.getMessage());
            return null;
        }
    }

    /** Reads the form, runs the action on the agents' loop, answers what it said (or 400 with why). */
    private void onLoop(HttpExchange x, java.util.function.Function<Map<String, String>, String> action) throws IOException {
        Map<String, String> params = form(x);
        if (params == null) {
            return;
        }
        java.net.InetSocketAddress client = x.getRemoteAddress();
        params.put(ConsoleView.CLIENT, client == null ? "" : client.getAddress().getHostAddress() + ":" + client.getPort());
        CompletableFuture<String> done = new CompletableFuture<>();
        console.platform().runtime().execute(() -> {
            try {
                done.complete(action.apply(params));
            } catch (RuntimeException e) {
                done.completeExceptionally(e);
            }
        });
        try {
            String said = done.get(10, TimeUnit.SECONDS);
            answer(x, 200, "application/json", json.createObjectNode().put("ok", true).put("message", said).toString());
        } catch (java.util.concurrent.ExecutionException e) {
            if (e.getCause() instanceof IllegalArgumentException) {
                refuse(x, 400, e.getCause().getMessage());
            } else {
                answer(x, 500, "text/plain", "the action failed: " + e.getCause());
            }
        } catch (java.util.concurrent.TimeoutException e) {
            answer(x, 503, "text/plain", "the agents did not take the action within 10 s");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static byte[] readBody(HttpExchange x) throws IOException {
        String len = x.getRequestHeaders().getFirst("Content-Length");
        if (len != null) {
            try {
                if (Long.parseLong(len.trim()) > MAX_BODY) {
                    return null;
                }
            } catch (NumberFormatException e) {
                return null;
            }
        }
        InputStream in = x.getRequestBody();
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        byte[] buf = new byte[1024];
        int n;
        while ((n = in.read(buf)) > 0) {
            b.write(buf, 0, n);
            if (b.size() > MAX_BODY) {
                return null;
            }
        }
        return b.toByteArray();
    }

    /** Starts or stops a recording: the same guards as an action; {@code name} names the file. */
    private void record(HttpExchange x, boolean start) throws IOException {
        if (!fromThePage(x)) {
            return;
        }
        Map<String, String> params = form(x);
        if (params == null) {
            return;
        }
        try {
            String said = start ? "recording to " + console.startRecording(params.get("name")).getFileName() : console.stopRecording();
            answer(x, 200, "application/json", json.createObjectNode().put("ok", true)
                    .put("message", said == null ? "no recording was under way" : start ? said : "recorded " + said).toString());
        } catch (IllegalArgumentException e) {
            refuse(x, 400, e.getMessage());
        }
    }

    private void recordings(HttpExchange x) throws IOException {
        Path dir = console.config().recordings();
        ObjectNode o = json.createObjectNode();
        Path now = console.recording();
        o.put("recording", now == null ? null : now.getFileName().toString());
        ArrayNode a = o.putArray("files");
        if (Files.isDirectory(dir)) {
            try (var s = Files.list(dir)) {
                for (Path p : s.sorted().toList()) {
                    String n = p.getFileName().toString();
                    if (Console.recordingName(n) && Files.isRegularFile(p)) {
                        a.addObject().put("name", n).put("bytes", Files.size(p));
                    }
                }
            }
        }
        answer(x, 200, "application/json", o.toString());
    }

    private void recordingFile(HttpExchange x, String name) throws IOException {
        if (!Console.recordingName(name)) {
            refuse(x, 400, "a recording is named by its file name (letters, digits, . _ -, ending in .jsonl), got '" + name + "'");
            return;
        }
        Path p = console.config().recordings().resolve(name);
        if (!Files.isRegularFile(p)) {
            refuse(x, 404, "no such recording: " + name + "; see /api/recordings");
            return;
        }
        answer(x, 200, "application/x-ndjson; charset=utf-8", Files.readAllBytes(p));
    }

    private void benchList(HttpExchange x) throws IOException {
        Path dir = console.config().reports();
        ArrayNode a = json.createArrayNode();
        if (dir != null && Files.isDirectory(dir)) {
            try (var s = Files.list(dir)) {
                s.map(p -> p.getFileName().toString()).filter(ConsoleServer::benchName).sorted().forEach(a::add);
            }
        }
        answer(x, 200, "application/json", a.toString());
    }

    static boolean benchName(String n) {
        return n.matches("[A-Za-z0-9][A-Za-z0-9._-]{0,100}") && (n.endsWith(".md") || n.endsWith(".png") || n.endsWith(".svg"));
    }

    private void benchFile(HttpExchange x, String name) throws IOException {
        Path dir = console.config().reports();
        if (!benchName(name) || name.contains("..")) {
            refuse(x, 400, "a report is named by its file name (letters, digits, . _ -; .md, .png or .svg), got '" + name + "'");
            return;
        }
        Path p = dir == null ? null : dir.resolve(name);
        if (p == null || !Files.isRegularFile(p)) {
            refuse(x, 404, "no such report: " + name);
            return;
        }
        String type = name.endsWith(".md") ? "text/markdown; charset=utf-8" : name.endsWith(".png") ? "image/png" : "image/svg+xml";
        answer(x, 200, type, Files.readAllBytes(p));
    }

    /** Parses {@code a=1&b=2}; every key once, at most 32 of them. */
    static Map<String, String> query(String raw) {
        Map<String, String> m = new LinkedHashMap<>();
        if (raw == null || raw.isEmpty()) {
            return m;
        }
        String[] parts = raw.split("&");
        if (parts.length > 32) {
            throw new IllegalArgumentException("more than 32 parameters");
        }
        for (String p : parts) {
            if (p.isEmpty()) {
                continue;
            }
            int eq = p.indexOf('=');
            String k = URLDecoder.decode(eq < 0 ? p : p.substring(0, eq), StandardCharsets.UTF_8);
            String v = eq < 0 ? "" : URLDecoder.decode(p.substring(eq + 1), StandardCharsets.UTF_8);
            if (m.put(k, v) != null) {
                throw new IllegalArgumentException("'" + k + "' given twice");
            }
        }
        return m;
    }

    private void refuse(HttpExchange x, int code, String why) throws IOException {
        refusals.computeIfAbsent("http-" + code, k -> new LongAdder()).increment();
        answer(x, code, "text/plain; charset=utf-8", why + "\n");
    }

    private static void answer(HttpExchange x, int code, String type, String body) throws IOException {
        answer(x, code, type, body.getBytes(StandardCharsets.UTF_8));
    }

    private static void answer(HttpExchange x, int code, String type, byte[] body) throws IOException {
        x.getResponseHeaders().set("Content-Type", type);
        x.getResponseHeaders().set("X-Content-Type-Options", "nosniff");
        boolean head = x.getRequestMethod().equals("HEAD");
        x.sendResponseHeaders(code, head ? -1 : body.length == 0 ? -1 : body.length);
        if (!head && body.length > 0) {
            try (OutputStream o = x.getResponseBody()) {
                o.write(body);
            }
        }
    }
}
