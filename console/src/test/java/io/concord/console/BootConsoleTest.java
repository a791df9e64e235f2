package io.concord.console;

import io.concord.layers.Boot;
import io.concord.layers.Platform;

import org.junit.jupiter.api.Test;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** {@code Boot -console}: found on the class path, started with the platform, its address printed, closed with it. */
class BootConsoleTest {

    @Test
    void bootServesTheConsoleAndPrintsWhereItIs() throws Exception {
        ByteArrayOutputStream text = new ByteArrayOutputStream();
        PrintStream out = new PrintStream(text, true, StandardCharsets.UTF_8);
        String uri;
        try (Platform p = Boot.start(new String[] {"-name", "boot-console", "-ports", "7561-7580", "-console", "127.0.0.1:0"}, out)) {
            String printed = text.toString(StandardCharsets.UTF_8);
            assertTrue(printed.startsWith("console: http://127.0.0.1:"), printed);
            uri = printed.substring("console: ".length()).trim();
            HttpResponse<String> r = HttpClient.newHttpClient().send(HttpRequest.newBuilder(URI.create(uri + "api/views")).build(),
                    HttpResponse.BodyHandlers.ofString());
            assertEquals(200, r.statusCode());
        }
        // Closed with the platform.
        assertThrows(java.io.IOException.class, () -> HttpClient.newHttpClient().send(HttpRequest.newBuilder(URI.create(uri)).build(),
                HttpResponse.BodyHandlers.ofString()));
    }

    @Test
    void aBadConsoleAddressSaysWhatIsWrong() {
        Boot.BootException e = assertThrows(Boot.BootException.class,
                () -> Boot.start(new String[] {"-name", "boot-console2", "-ports", "7581-7590", "-console", "seventy"}, System.out));
        assertTrue(e.getMessage().contains("[host:]port"), e.getMessage());
    }
}
