package io.concord.console;

import io.concord.core.acl.AID;
import io.concord.core.net.Address;
import io.concord.layers.Platform;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.UnknownHostException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.SecureRandom;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * The web console: a page any JVM of the platform can serve, showing the platform's lists, the
 * safety counters, the messages between the agents a browser picks, the bench's reports and the
 * views an application adds (the hospital's map). Opt-in; binds 127.0.0.1 unless told otherwise,
 * and on any other address asks every request for the token.
 *
 * <pre>{@code
 * Console c = Console.start(platform, Console.Config.port(7070));
 * System.out.println("console: " + c.uri());
 * }</pre>
 */
public final class Console implements AutoCloseable {

    /**
     * Settings.
     *
     * @param host        the address to bind: 127.0.0.1 by default; any other asks for the token
     * @param port        the port (0: any free one)
     * @param token       the token; {@code null}: a random one when the address is not loopback
     * @param reports     the bench's report directory shown in the bench view ({@code bench/report} if it exists)
     * @param keep        sniffed messages kept for browsers that open later
     * @param maxBrowsers event streams open at once
     * @param agentName   the console agent's local name
     * @param recordings  where recordings are written and read ({@code recordings} in the working directory by default)
     */
    public record Config(String host, int port, String token, Path reports, int keep, int maxBrowsers, String agentName, Path recordings) {
        public Config {
            Objects.requireNonNull(host, "host");
            if (port < 0 || port > 65535) {
                throw new IllegalArgumentException("the console's port must be 0 to 65535, got " + port);
            }
            if (keep < 1 || maxBrowsers < 1) {
                throw new IllegalArgumentException("keep and maxBrowsers must be at least 1");
            }
            if (token != null && token.length() < 16) {
                throw new IllegalArgumentException("a console token must have at least 16 characters");
            }
            Objects.requireNonNull(recordings, "recordings");
        }

        /** Loopback, this port, the defaults. */
        public static Config port(int port) {
            Path reports = Path.of("bench", "report");
            return new Config("127.0.0.1", port, null, Files.isDirectory(reports) ? reports : null, 1_000, 16, "console", Path.of("recordings"));
        }

        /**
         * From {@code [host:]port}, as {@code Boot -console} and the demo's {@code --console} take it.
         *
         * @throws IllegalArgumentException saying what is wrong
         */
        public static Config parse(String hostPort) {
            String s = hostPort.trim();
            Address a = s.contains(":") ? Address.parse(s) : null;
            if (a == null && !s.matches("[0-9]{1,5}")) {
                throw new IllegalArgumentException("the console is given as [host:]port, e.g. 7070 or 0.0.0.0:7070; got '" + hostPort + "'");
            }
            return a != null ? port(a.port()).withHost(a.host()) : port(Integer.parseInt(s));
        }

        public Config withHost(String h) {
            return new Config(h, port, token, reports, keep, maxBrowsers, agentName, recordings);
        }

        public Config withToken(String t) {
            return new Config(host, port, t, reports, keep, maxBrowsers, agentName, recordings);
        }

        public Config withReports(Path r) {
            return new Config(host, port, token, r, keep, maxBrowsers, agentName, recordings);
        }

        public Config withKeep(int k) {
            return new Config(host, port, token, reports, k, maxBrowsers, agentName, recordings);
        }

        public Config withRecordings(Path dir) {
            return new Config(host, port, token, reports, keep, maxBrowsers, agentName, dir);
        }

        public Config withAgentName(String n) {
            return new Config(host, port, token, reports, keep, maxBrowsers, n, recordings);
        }
    }

    private final Platform platform;
    private final Config config;
    private final Hub hub;
    private final List<ConsoleView> views = new CopyOnWriteArrayList<>();
    private final ConsoleAgent agent;
    private final AID aid;
    private final ConsoleServer server;
    private final String token;

    private Console(Platform platform, Config config, HttpLoop.Limits limits, java.util.function.LongSupplier nanos) {
        this.platform = platform;
        this.config = config;
        InetAddress bind;
        try {
            bind = InetAddress.getByName(config.host());
        } catch (UnknownHostException e) {
            throw new IllegalArgumentException("the console cannot bind '" + config.host() + "': no such address", e);
        }
        this.token = bind.isLoopbackAddress() ? config.token() : config.token() != null ? config.token() : newToken();
        this.hub = new Hub(config.keep(), config.maxBrowsers());
        this.agent = new ConsoleAgent(hub, views);
        try {
            this.server = new ConsoleServer(new InetSocketAddress(bind, config.port()), token, !bind.isLoopbackAddress(), hub, this,
                    limits, nanos);
        } catch (IOException e) {
            throw new UncheckedIOException("the console cannot listen on " + config.host() + ":" + config.port() + ": " + e.getMessage()
                    + " (is another program on that port? give another with [host:]port, or 0 for any)", e);
        }
        this.aid = platform.startAgent(config.agentName(), agent);
        server.start();
    }

    private static String newToken() {
        byte[] b = new byte[16];
        new SecureRandom().nextBytes(b);
        return HexFormat.of().formatHex(b);
    }

    /**
     * Starts the console's agent on the platform and its web server.
     *
     * @throws IllegalArgumentException if the address cannot be bound here
     * @throws UncheckedIOException     if the port is taken
     */
    public static Console start(Platform platform, Config config) {
        return new Console(platform, config, HttpLoop.Limits.DEFAULT, System::nanoTime);
    }

    /** With the HTTP server's limits and clock given: for tests, which shorten a limit or move the time. */
    static Console start(Platform platform, Config config, HttpLoop.Limits limits, java.util.function.LongSupplier nanos) {
        return new Console(platform, config, limits, nanos);
    }

    /** The HTTP server, for tests (its sweep, its connections). */
    ConsoleServer server() {
        return server;
    }

    /** Adds a view (a tab); browsers see it when they load the page. */
    public Console addView(ConsoleView v) {
        if (!v.id().matches("[a-z0-9-]{1,32}")) {
            throw new IllegalArgumentException("a view's id is 1 to 32 of a-z, 0-9 and '-', got '" + v.id() + "'");
        }
        views.add(v);
        return this;
    }

    /** An operator's action on the agents (start, kill, send); on the loop. */
    String agentAction(String action, Map<String, String> params) {
        return agent.act(action, params, platform);
    }

    List<ConsoleView> views() {
        return views;
    }

    Config config() {
        return config;
    }

    Platform platform() {
        return platform;
    }

    /** The page's address, with the token if one is needed. */
    public String uri() {
        InetSocketAddress a = server.address();
        String host = a.getAddress().isAnyLocalAddress() ? "127.0.0.1" : a.getAddress().getHostAddress();
        if (host.contains(":")) {
            host = "[" + host + "]";
        }
        return "http://" + host + ":" + a.getPort() + "/" + (token == null ? "" : "?token=" + token);
    }

    /** The port it listens on. */
    public int port() {
        return server.address().getPort();
    }

    /** The token every request must carry, or {@code null} on loopback without one. */
    public String token() {
        return token;
    }

    /** The console agent's name on the platform. */
    public AID agent() {
        return aid;
    }

    /**
     * What the console refused or dropped, by reason: {@code console-slow-client} (events a slow
     * browser could not take), {@code console-busy} (streams refused over the limit),
     * {@code console-malformed} (agent reports that were not JSON), the HTTP answers 4xx by code
     * ({@code http-404}...), and the connections the HTTP server closed for a limit:
     * {@code http-slow} (a request not whole within its time), {@code http-slow-reader} (an answer
     * not taken within its time), {@code http-connections} (closed for a newer one at a cap).
     */
    public Map<String, Long> drops() {
        Map<String, Long> m = new TreeMap<>(server.refusals());
        m.put("console-slow-client", hub.slowDrops.get());
        m.put("console-busy", hub.refused.get());
        m.put("console-malformed", agent.malformed.get());
        return m;
    }

    /** A recording's file name: letters, digits, '.', '_', '-', ending in .jsonl. */
    static boolean recordingName(String n) {
        return n.matches("[A-Za-z0-9][A-Za-z0-9._-]{0,100}\\.jsonl") && !n.contains("..");
    }

    /**
     * Records from now on everything the console shows (the platform's lists, the safety counters,
     * the sniffed messages, every view: the hospital's poses) into {@code recordings/name}, to be
     * played back in the page with a time slider. Thread-safe.
     *
     * @param name the file's name ({@code run-1.jsonl}), or {@code null} for one made from the time
     * @return the file
     * @throws IllegalArgumentException if the name is not a recording's, the file exists, or a recording is under way
     */
    public synchronized Path startRecording(String name) {
        if (hub.recording()) {
            throw new IllegalArgumentException("a recording is under way (" + hub.recorder().file().getFileName() + "); stop it first");
        }
        String n = name == null || name.isBlank()
                ? "run-" + java.time.LocalDateTime.now().format(java.time.format.DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss")) + ".jsonl"
                : name.trim();
        if (!recordingName(n)) {
            throw new IllegalArgumentException("a recording is named with letters, digits, '.', '_' and '-', ending in .jsonl; got '" + n + "'");
        }
        Path f = config.recordings().resolve(n);
        if (Files.exists(f)) {
            throw new IllegalArgumentException("there is a recording " + n + " already; give another name");
        }
        try {
            Recorder old = hub.record(new Recorder(f));
            if (old != null) {
                old.close();   // one that stopped by itself (full, or its disk failed)
            }
        } catch (IOException e) {
            throw new IllegalArgumentException("cannot write " + f + ": " + e.getMessage() + " (Console.Config.withRecordings sets the directory)");
        }
        return f;
    }

    /** Stops the recording under way and says what it holds; {@code null} if there was none. */
    public synchronized String stopRecording() {
        Recorder r = hub.record(null);
        if (r == null) {
            return null;
        }
        r.close();
        return r.file().getFileName() + ": " + r.events() + " events, " + (r.bytes() >> 10) + " KiB, " + r.dropped() + " dropped"
                + (r.dropped() > 0 ? " (the disk was slower than the events)" : "")
                + (r.failure() != null ? "; " + r.failure() : "");
    }

    /** The recording under way, or {@code null}. */
    public Path recording() {
        Recorder r = hub.recorder();
        return r == null ? null : r.file();
    }

    /** Browsers with an event stream open. */
    public int browsers() {
        return hub.open();
    }

    @Override
    public void close() {
        stopRecording();
        server.stop();
        agent.doDelete();   // it leaves the platform cleanly (from any thread)
    }
}
