package io.concord.layers;

import io.concord.layers.platform.Gateway;

import java.util.Map;
import java.util.ServiceLoader;

/**
 * Makes gateways of one kind, found with {@link ServiceLoader} (as core finds the default
 * stack): {@code concord-jade-bridge} provides {@code "http"}, the JADE HTTP MTP, so that
 * {@code Boot -http 7779} needs nothing but that jar on the class path.
 */
public interface GatewayProvider {

    /** The kind, as Boot's option names it: {@code "http"}. */
    String kind();

    /** A gateway listening on the host and port (each container that serves it makes its own). */
    Gateway create(String host, int port);

    /**
     * ... with the kind's own settings ({@code http-platforms}, {@code http-hosts} for the HTTP
     * MTP: comma-separated names and addresses it trusts); by default they are ignored.
     */
    default Gateway create(String host, int port, Map<String, String> settings) {
        return create(host, port);
    }
}
