package jade.wrapper;

/** The agent or container behind a controller is gone, or could not be made. */
public class StaleProxyException extends ControllerException {
    private static final long serialVersionUID = 1L;

    public StaleProxyException() {
    }

    public StaleProxyException(String msg) {
        super(msg);
    }

    public StaleProxyException(Throwable cause) {
        super(cause);
    }
}
