package jade.wrapper;

/** A container or agent controller could not do what was asked. */
public class ControllerException extends Exception {
    private static final long serialVersionUID = 1L;

    public ControllerException() {
    }

    public ControllerException(String msg) {
        super(msg);
    }

    public ControllerException(Throwable cause) {
        super(cause);
    }
}
