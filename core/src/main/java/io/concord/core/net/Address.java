package io.concord.core.net;

import java.util.Objects;

/**
 * A transport address: a host (an IP literal for real sockets, a name for virtual hosts) and a
 * port. Written {@code udp://host:port} in AIDs.
 */
public record Address(String host, int port) {
    /** The scheme prefix of Concord datagram addresses in AIDs. */
    public static final String UDP_SCHEME = "udp://";

    public Address {
        Objects.requireNonNull(host, "host");
        if (port < 0 || port > 65535) {
            throw new IllegalArgumentException("port must be 0..65535, got " + port);
        }
    }

    /** This address as an AID transport address, {@code udp://host:port}. */
    public String toUri() {
        return toUri(Transport.UDP);
    }

    /** This address as an AID transport address of the given transport. */
    public String toUri(Transport transport) {
        return transport.scheme() + host + ":" + port;
    }

    /**
     * Parses {@code udp://host:port}, {@code tcp://host:port} or {@code host:port}.
     *
     * @return the address, or {@code null} if the text is not one
     */
    public static Address parse(String uri) {
        String s = uri;
        if (s.regionMatches(true, 0, UDP_SCHEME, 0, UDP_SCHEME.length())) {
            s = s.substring(UDP_SCHEME.length());
        } else if (s.regionMatches(true, 0, "tcp://", 0, 6)) {
            s = s.substring(6);
        } else if (s.contains("://")) {
            return null;
        }
        int slash = s.indexOf('/');
        if (slash >= 0) {
            s = s.substring(0, slash);
        }
        int colon = s.lastIndexOf(':');
        if (colon <= 0 || colon == s.length() - 1) {
            return null;
        }
        String host = s.substring(0, colon);
        if (host.startsWith("[") && host.endsWith("]")) {
            host = host.substring(1, host.length() - 1);
        }
        int port = 0;
        for (int i = colon + 1; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c < '0' || c > '9' || port > 65535) {
                return null;
            }
            port = port * 10 + (c - '0');
        }
        return port <= 65535 ? new Address(host, port) : null;
    }

    @Override
    public String toString() {
        return host + ":" + port;
    }
}
