package io.concord.jade;

import io.concord.core.acl.AID;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.util.HexFormat;
import java.util.Locale;
import java.util.Map;

/**
 * The HTTP MTP's client: POSTs a message to another platform's ACC as JADE sends and reads it
 * (a multipart body of the XML envelope and the ACL string), on a kept-alive connection when the
 * peer allows. Used by the gateway's one out thread only.
 */
final class MtpClient {
    // Kept-alive connections to other platforms' ACCs, by host:port; used by the out thread only.
    private final Map<String, Connection> connections = new java.util.HashMap<>();

    /** Closes every kept-alive connection (on the out thread). */
    void close() {
        for (Connection c : connections.values()) {
            try {
                c.socket().close();
            } catch (IOException ignored) {
                // closing anyway
            }
        }
        connections.clear();
    }

    /** A socket and its buffered input: a response is read a buffer at a time, not a byte a system call. */
    private record Connection(Socket socket, InputStream in) {
        static Connection open(String host, int port) throws IOException {
            Socket s = new Socket();
            try {
                s.setTcpNoDelay(true); // one write, sent at once: no Nagle wait for a delayed ACK
                s.connect(new InetSocketAddress(host, port), 5_000);
                s.setSoTimeout(10_000);
                return new Connection(s, new java.io.BufferedInputStream(s.getInputStream(), 4096));
            } catch (IOException e) {
                s.close();
                throw e;
            }
        }
    }

    /** One POST, as JADE reads it, on a kept-alive connection when the peer allows; returns the status. */
    int post(String url, AID receiver, AID sender, String payload) throws IOException {
        URI u = URI.create(url);
        int p = u.getPort() < 0 ? 80 : u.getPort();
        byte[] request = request(url, u.getHost(), p, receiver, sender, payload);
        String key = u.getHost() + ":" + p;
        for (int attempt = 0; ; attempt++) {
            Connection c = connections.remove(key);
            boolean reused = c != null;
            if (c == null) {
                c = Connection.open(u.getHost(), p);
            }
            try {
                OutputStream o = c.socket().getOutputStream();
                o.write(request);
                o.flush();
                Response r = readResponse(c.in(), url);
                if (r.keepAlive()) {
                    connections.put(key, c);
                } else {
                    c.socket().close();
                }
                return r.status();
            } catch (IOException e) {
                c.socket().close();
                if (!reused || attempt > 0) {
                    throw e;
                }
                // the peer closed a kept-alive connection meanwhile: once more on a new one
            }
        }
    }

    private record Response(int status, boolean keepAlive) {
    }

    private static byte[] request(String url, String host, int port, AID receiver, AID sender, String payload) {
        byte[] acl = payload.getBytes(StandardCharsets.UTF_8);
        FipaEnvelope env = FipaEnvelope.forOne(receiver, sender, acl.length);
        byte[] rnd = new byte[16];
        java.util.concurrent.ThreadLocalRandom.current().nextBytes(rnd);
        String boundary = HexFormat.of().formatHex(rnd).substring(1);
        ByteArrayOutputStream body = new ByteArrayOutputStream(acl.length + 1024);
        body.writeBytes(("This is not part of the MIME multipart encoded message.\r\n--" + boundary
                + "\r\nContent-Type: application/xml\r\n\r\n" + env.toXml() + "\r\n--" + boundary
                + "\r\nContent-Type: application/text; charset=UTF-8\r\n\r\n").getBytes(StandardCharsets.UTF_8));
        body.writeBytes(acl);
        body.writeBytes(("\r\n--" + boundary + "--\r\n").getBytes(StandardCharsets.UTF_8));
        String head = "POST " + url + " HTTP/1.1\r\nCache-Control: no-cache\r\nMime-Version: 1.0\r\nHost: " + host
                + ":" + port + "\r\nContent-Type: multipart/mixed ; boundary=\"" + boundary + "\"\r\nContent-Length: "
                + body.size() + "\r\nConnection: Keep-Alive\r\n\r\n";
        ByteArrayOutputStream all = new ByteArrayOutputStream(head.length() + body.size());
        all.writeBytes(head.getBytes(StandardCharsets.US_ASCII));
        all.writeBytes(body.toByteArray());
        return all.toByteArray();
    }

    /**
     * Reads a response: the status line (after any blank lines), the headers, and the body when the
     * connection stays open: by Content-Length, or JADE's fixed HTML page, which has none.
     */
    private static Response readResponse(InputStream in, String url) throws IOException {
        String line;
        do {
            line = readLine(in);
            if (line == null) {
                throw new IOException("no HTTP status from " + url);
            }
        } while (line.isEmpty());
        if (!line.startsWith("HTTP/1.")) {
            throw new IOException("not an HTTP response from " + url + ": " + line);
        }
        String[] w = line.split(" ");
        int status = w.length > 1 ? Integer.parseInt(w[1]) : 500;
        boolean keepAlive = line.startsWith("HTTP/1.1");
        int length = -1;
        while ((line = readLine(in)) != null && !line.isEmpty()) {
            String l = line.toLowerCase(Locale.ROOT);
            if (l.startsWith("connection:")) {
                keepAlive = l.substring(11).trim().equals("keep-alive");
            } else if (l.startsWith("content-length:")) {
                length = Integer.parseInt(l.substring(15).trim());
            }
        }
        if (!keepAlive) {
            return new Response(status, false);
        }
        if (length >= 0) {
            in.readNBytes(length);
            return new Response(status, true);
        }
        // JADE's page: <html><body><h1>200 OK</h1></body></html>, without a length.
        StringBuilder b = new StringBuilder();
        int c;
        while (b.length() < 4096 && (c = in.read()) >= 0) {
            b.append((char) c);
            if (b.length() >= 7 && b.substring(b.length() - 7).equalsIgnoreCase("</html>")) {
                return new Response(status, true);
            }
        }
        return new Response(status, false);
    }

    private static String readLine(InputStream in) throws IOException {
        StringBuilder b = new StringBuilder();
        int c;
        while ((c = in.read()) >= 0) {
            if (c == '\n') {
                int n = b.length();
                return n > 0 && b.charAt(n - 1) == '\r' ? b.substring(0, n - 1) : b.toString();
            }
            b.append((char) c);
            if (b.length() > 8192) {
                throw new IOException("an HTTP header line longer than 8 KiB");
            }
        }
        return b.length() == 0 ? null : b.toString();
    }
}
