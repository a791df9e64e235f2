package io.concord.bench.child;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.codec.StringAclCodec;
import io.concord.jade.FipaEnvelope;

import java.io.BufferedInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.util.Locale;

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
        byte[] acl = StringAclCodec.INSTANCE.encodeForJade(inform).getBytes(StandardCharsets.UTF_8);
        String boundary = "a36869921a26b9d812878b42b8fc2cd";
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        b.writeBytes(("This is not part of the MIME multipart encoded message.\r\n--" + boundary
                + "\r\nContent-Type: application/xml\r\n\r\n" + FipaEnvelope.forOne(requester, echo, acl.length).toXml()
                + "\r\n--" + boundary + "\r\nContent-Type: application/text; charset=UTF-8\r\n\r\n")
                .getBytes(StandardCharsets.UTF_8));
        b.writeBytes(acl);
        b.writeBytes(("\r\n--" + boundary + "--\r\n").getBytes(StandardCharsets.UTF_8));
        URI u = URI.create(address);
        String head = String.format(Locale.ROOT, "POST %s HTTP/1.1\r\nCache-Control: no-cache\r\nMime-Version: 1.0\r\n"
                + "Host: %s:%d\r\nContent-Type: multipart/mixed ; boundary=\"%s\"\r\nContent-Length: %d\r\n"
                + "Connection: Keep-Alive\r\n\r\n", address, u.getHost(), u.getPort(), boundary, b.size());
        ByteArrayOutputStream all = new ByteArrayOutputStream();
        all.writeBytes(head.getBytes(StandardCharsets.US_ASCII));
        all.writeBytes(b.toByteArray());
        return all.toByteArray();
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
