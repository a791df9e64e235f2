package io.concord.jade;

import io.concord.core.acl.AID;
import io.concord.layers.Boot;
import io.concord.layers.platform.ContainerLayer;
import io.concord.layers.Platform;
import io.concord.layers.platform.Role;
import org.junit.jupiter.api.Test;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** {@code Boot -http} finds the HTTP MTP by ServiceLoader when this jar is on the class path, and its container serves it. */
class BootHttpTest {

    /** Boots one agent with the ACC and the extra arguments, waits until it serves, and POSTs JADE's request. */
    private static int postJadeRequest(String name, String ports, String... extra) throws Exception {
        int port = JadeBridgeTest.freePort();
        java.util.List<String> args = new java.util.ArrayList<>(java.util.List.of("-name", name, "-ports", ports, "-profile", "closed",
                "-http", Integer.toString(port), "-agents", "echo:io.concord.testkit.EchoAgent"));
        args.addAll(java.util.List.of(extra));
        try (Platform p = Boot.start(args.toArray(new String[0]), new PrintStream(new ByteArrayOutputStream()))) {
            // The agent is alone, so container at once; its gateway starts as it takes the role.
            CompletableFuture<Void> container = new CompletableFuture<>();
            p.runtime().execute(() -> {
                ContainerLayer l = Platform.containerLayer(p.runtime(), AID.local("echo", name));
                Consumer<ContainerLayer> check = x -> {
                    if (x.role() == Role.CONTAINER) {
                        container.complete(null);
                    }
                };
                l.addListener(check);
                check.accept(l);
            });
            container.get(20, TimeUnit.SECONDS);
            HttpClient c = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
            HttpRequest get = HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + port + "/acc")).GET().build();
            assertEquals(405, c.send(get, HttpResponse.BodyHandlers.discarding()).statusCode(), "the ACC answers (it takes POST only)");
            String body = WireTest.JADE_BODY.replace("bob@foreignplat", "echo@" + name);
            HttpRequest post = HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + port + "/acc"))
                    .header("Content-Type", "multipart/mixed ; boundary=\"7b446481f5ae2c17c233efb80dd6246\"")
                    .POST(HttpRequest.BodyPublishers.ofString(body)).build();
            return c.send(post, HttpResponse.BodyHandlers.discarding()).statusCode();
        }
    }

    @Test
    void bootWithHttpServesTheAccOnceItsContainerIsElected() throws Exception {
        assertEquals(200, postJadeRequest("boothttp", "7791-7799"));
    }

    @Test
    void aBridgeRestrictedToOtherJadePlatformsRefusesTheRest() throws Exception {
        assertEquals(403, postJadeRequest("trusthosts", "7791-7799", "-http-hosts", "10.200.0.9"),
                "a request from an address the bridge does not trust");
        assertEquals(403, postJadeRequest("trustplat", "7791-7799", "-http-platforms", "10.200.0.9:1099/JADE"),
                "a message from an agent of a platform the bridge does not trust");
        assertEquals(200, postJadeRequest("trustboth", "7791-7799", "-http-hosts", "127.0.0.1", "-http-platforms", "testplat"),
                "the platform and address it trusts (names compare ignoring case)");
    }
}
