package io.concord.bench.child;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.codec.StringAclCodec;

import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.URI;
import java.nio.charset.StandardCharsets;

/**
 * The floor of the HTTP benchmark: the least an HTTP MTP can do to answer a JADE agent's REQUEST.
 * It reads each POST by its length, answers 200 on the kept-alive connection, and posts back an
 * INFORM whose bytes (head, envelope, payload) were written once, at the first request, on one
 * kept-alive connection of its own: no parsing, no platform, no thread hand-off. What remains of a
 * request and reply is JADE's side of it, which no other platform can make shorter.
 */
final class HttpFloor {
    private final ServerSocket server;
    private volatile byte[] reply;
    private Socket out;
    private InputStream outIn;

    HttpFloor(int port) throws IOException {
        server = new ServerSocket();
        server.setReuseAddress(true);
        server.bind(new InetSocketAddress("127.0.0.1", port));
        Thread t = new Thread(this::accept, "http-floor");
        t.setDaemon(true);
        t.start();
    }

    private void accept() {
        try {
            while (true) {
                Socket s = server.accept();
                s.setTcpNoDelay(true);
                Thread t = new Thread(() -> serve(s), "http-floor-conn");
                t.setDaemon(true);
                t.start();
            }
        } catch (IOException closed) {
            // the server is gone
        }
    }

    private void serve(Socket s) {
        try (s) {
            InputStream in = new BufferedInputStream(s.getInputStream(), 16 * 1024);
            OutputStream o = s.getOutputStream();
            while (true) {
                int length = -1;
                String line;
                do {
                    line = readLine(in);
                    if (line == null) {
                        return;
                    }
                } while (line.isEmpty());
                while ((line = readLine(in)) != null && !line.isEmpty()) {
                    if (line.regionMatches(true, 0, "content-length:", 0, 15)) {
                        length = Integer.parseInt(line.substring(15).trim());
                    }
                }
                byte[] body = in.readNBytes(length);
                o.write("HTTP/1.1 200 OK\r\nConnection: Keep-Alive\r\nContent-Length: 0\r\n\r\n".getBytes(StandardCharsets.US_ASCII));
                o.flush();
                answer(body);
            }
        } catch (IOException | RuntimeException e) {
            // the client went away
        }
    }

    /** Posts the INFORM back on the one outgoing connection (requests come one at a time). */
    private synchronized void answer(byte[] body) throws IOException {
        if (reply == null) {
            reply = template(new String(body, StandardCharsets.UTF_8));
        }
        if (out == null) {
            URI u = URI.create(address);
            out = new Socket(u.getHost(), u.getPort());
            out.setTcpNoDelay(true);
            outIn = new BufferedInputStream(out.getInputStream(), 4096);
        }
        out.getOutputStream().write(reply);
        // JADE's answer: a status line, headers, a blank line and <html>...</html> with no length.
        StringBuilder b = new StringBuilder();
        int c;
        while ((c = outIn.read()) >= 0) {
            b.append((char) c);
            if (b.length() >= 7 && b.lastIndexOf("</html>") == b.length() - 7) {
                return;
            }
        }
        throw new IOException("JADE closed the connection");
    }

    private String address;

    /** The INFORM's bytes, from the first request's ACL payload: its sender is the one to answer. */
    private byte[] template(String body) throws IOException {
        int at = body.indexOf("(REQUEST");
        int end = body.lastIndexOf(')');
        AclMessage request;
        try {
            request = StringAclCodec.INSTANCE.decode(body.substring(at, end + 1));
        } catch (io.concord.core.codec.AclParseException e) {
            throw new IOException("not a JADE request: " + e.getMessage(), e);
        }
        AID requester = request.getSender();
        address = requester.addresses().get(0);
        AID echo = new AID("echo@httptarget", "http://127.0.0.1:" + server.getLocalPort() + "/acc");
        AclMessage inform = new AclMessage(Performative.INFORM);
        inform.setSender(echo);
        inform.addReceiver(requester);
        inform.setContent(request.getContent());
        // The bytes the bridge itself would post: only how often they are made differs.
        return io.concord.jade.HttpMtp.jadePost(address, requester, echo, StringAclCodec.INSTANCE.encodeForJade(inform));
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
        }
        return b.length() == 0 ? null : b.toString();
    }

    void close() throws IOException {
        server.close();
        if (out != null) {
            out.close();
        }
    }
}
