package io.concord.console;

import org.openqa.selenium.OutputType;
import org.openqa.selenium.TakesScreenshot;
import org.openqa.selenium.WebDriver;
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.chrome.ChromeDriverService;
import org.openqa.selenium.chrome.ChromeOptions;
import org.openqa.selenium.support.ui.WebDriverWait;

import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.function.Function;

/**
 * A real headless Chromium driven by chromium-driver (Debian's {@code chromium} and
 * {@code chromium-driver}, which CI installs), for the console's browser tests.
 */
public final class Browser implements AutoCloseable {
    public final WebDriver driver;

    public Browser() {
        String chromium = System.getProperty("concord.chromium", "/usr/bin/chromium");
        String driverPath = System.getProperty("concord.chromedriver", "/usr/bin/chromedriver");
        if (!new File(chromium).canExecute() || !new File(driverPath).canExecute()) {
            throw new IllegalStateException("the browser tests need Chromium and its driver: apt-get install chromium chromium-driver "
                    + "(or -Dconcord.chromium=... -Dconcord.chromedriver=...); not found: " + chromium + ", " + driverPath);
        }
        ChromeOptions o = new ChromeOptions();
        o.setBinary(chromium);
        o.addArguments("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--disable-gpu", "--window-size=1600,1043",
                "--no-first-run", "--no-default-browser-check", "--disable-extensions", "--disable-background-networking");
        ChromeDriverService s = new ChromeDriverService.Builder().usingDriverExecutable(new File(driverPath)).usingAnyFreePort().build();
        driver = new ChromeDriver(s, o);
    }

    /** Waits for a condition the page will reach (up to 30 s: a guard, not a timing). */
    public <T> T until(Function<WebDriver, T> condition) {
        return new WebDriverWait(driver, Duration.ofSeconds(30), Duration.ofMillis(50))
                .ignoring(org.openqa.selenium.StaleElementReferenceException.class).until(condition);
    }

    /** Writes what the browser shows to {@code target/screenshots/name.png}. */
    /** Every line of a recording the console wrote in {@code target/recordings}, read as JSON. */
    public static java.util.List<com.fasterxml.jackson.databind.JsonNode> recording(String name) throws IOException {
        com.fasterxml.jackson.databind.ObjectMapper json = new com.fasterxml.jackson.databind.ObjectMapper();
        java.util.List<com.fasterxml.jackson.databind.JsonNode> lines = new java.util.ArrayList<>();
        for (String l : Files.readAllLines(Path.of("target", "recordings", name))) {
            lines.add(json.readTree(l));
        }
        return lines;
    }

    /**
     * Moves the Replay tab's slider to the recording's time {@code atMs} ({@code t0Ms}: its first
     * line's) and waits until the page shows that moment.
     */
    public void slideTo(long t0Ms, long atMs) {
        ((org.openqa.selenium.JavascriptExecutor) driver).executeScript(
                "const s = document.getElementById('replay-slider'); s.value = arguments[0]; s.dispatchEvent(new Event('input'));", atMs - t0Ms);
        until(d -> String.valueOf(atMs).equals(d.findElement(org.openqa.selenium.By.id("replay-time")).getAttribute("data-t")));
    }

    public Path screenshot(String name) {
        try {
            Path dir = Path.of("target", "screenshots");
            Files.createDirectories(dir);
            Path p = dir.resolve(name + ".png");
            Files.write(p, ((TakesScreenshot) driver).getScreenshotAs(OutputType.BYTES));
            return p;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Override
    public void close() {
        driver.quit();
    }
}
